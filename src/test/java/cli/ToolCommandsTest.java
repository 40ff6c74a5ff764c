package cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The report, robustness and benchmark subcommands: bad input is exit code 2 with the allowed values named. */
class ToolCommandsTest {
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        return RaytracerCli.run(args, new PrintWriter(new StringWriter(), true), new PrintWriter(err, true));
    }

    @Test
    void unknownBenchmarkIsBadInputNamingTheAllowedOnes() {
        assertEquals(ExitCodes.BAD_INPUT, run("benchmark", "nope"));
        assertTrue(err.toString().contains("allowed: bvh, planning, render, effects"), err.toString());
    }

    @Test
    void renderBenchmarkRejectsUnknownScenesAndMissingBaselines() {
        assertEquals(ExitCodes.BAD_INPUT, run("benchmark", "render", "--only", "nope"));
        assertTrue(
                err.toString()
                        .contains("--only: unknown scene 'nope'; allowed: street-hard, street-main, showcase,"
                                + " glass-and-mirror"),
                err.toString());
        assertEquals(ExitCodes.BAD_INPUT, run("benchmark", "render", "--baseline", "no-such.csv"));
        assertTrue(err.toString().contains("--baseline no-such.csv: no such file"), err.toString());
    }

    /** A run that would write its images over the baseline's (and compare each with itself) is refused. */
    @Test
    void renderBenchmarkRefusesToWriteOverTheBaselinesImages(@TempDir Path dir) throws Exception {
        Path images = dir.resolve("base-img");
        Path csv = dir.resolve("base.csv");
        String header = "scenario,wall_s,cpu_s,camera,shadow,reflection,refraction,node_visits,primitive_tests,"
                + "bytes_per_ray,image";
        Files.writeString(
                csv, header + "\n" + "street-hard/1T,0.5,0.5,1,1,1,1,1,1,0," + images.resolve("a.png") + "\n");
        assertEquals(
                ExitCodes.BAD_INPUT,
                run("benchmark", "render", "--baseline", csv.toString(), "--images", images.toString()));
        assertTrue(
                err.toString().contains("keeps its images in this folder; give this run another one"), err.toString());
    }

    @Test
    void malformedBenchmarkArgumentsAreBadInput() {
        assertEquals(ExitCodes.BAD_INPUT, run("benchmark", "planning", "many"));
        assertEquals(ExitCodes.BAD_INPUT, run("benchmark", "bvh", "runs"));
    }

    @Test
    void badReportOptionsAreBadInput() {
        assertEquals(ExitCodes.BAD_INPUT, run("report", "--size", "3x3"));
        assertTrue(err.toString().contains("8x8"), err.toString());
        assertEquals(ExitCodes.BAD_INPUT, run("report", "--counts", "16"));
        assertEquals(ExitCodes.BAD_INPUT, run("robustness", "--probes", "5"));
        assertTrue(err.toString().contains("--probes"), err.toString());
    }

    /** Every numeric argument of the tool commands is bounded: one line and exit 2, never a crash or a runaway. */
    @Test
    void everyNumericToolArgumentIsBounded() {
        String[][] cases = {
            {"benchmark planning -5", "runs must be in [1, 1000], but was -5"},
            {"benchmark planning many", "benchmark planning: 'many' is not an integer"},
            {"benchmark effects 3 0 5", "width and height must be at least 1"},
            {"benchmark effects 3 100000 100000", "hold at most 2^24 pixels"},
            {"benchmark bvh runs=0", "runs must be in [1, 1000], but was 0"},
            {"benchmark bvh threads=0", "threads must be in [1, 256], but was 0"},
            {"benchmark render --runs 5000", "--runs must be in [1, 1000], but was 5000"},
            {"benchmark render --threads 0", "--threads must be in [1, 256], but was 0"},
            {"report --size 8", "--size must be WxH"},
            {"report --size 100000x100000", "--size must be from 8x8 to 4096x4096"},
            {"report --counts 0,4", "--counts: each must be in [1, 1048576], but was 0"},
            {"report --counts 4,2000000", "but was 2000000"},
            {"report --repeats 0", "--repeats must be in [1, 1000], but was 0"},
            {"robustness --probes 2000000000", "--probes must be in [100, 10000000], but was 2000000000"},
        };
        for (String[] c : cases) {
            err.getBuffer().setLength(0);
            assertEquals(ExitCodes.BAD_INPUT, run(c[0].split(" ")), c[0] + ": " + err);
            assertTrue(err.toString().startsWith("error: "), c[0] + ": " + err);
            assertTrue(err.toString().contains(c[1]), c[0] + ": " + err);
            assertEquals(1, err.toString().strip().lines().count(), c[0] + ": " + err);
        }
    }

    @Test
    void aTinyReportWritesItsCharts(@TempDir Path out) {
        assertEquals(
                ExitCodes.OK,
                run("report", "--size", "12x9", "--counts", "1,4", "--repeats", "1", "--out", out.toString()));
        for (String slug : new String[] {"aa", "shadows", "dof", "glossy"}) {
            assertTrue(Files.exists(out.resolve("accuracy-" + slug + ".png")), slug);
        }
        assertTrue(Files.exists(out.resolve("accuracy").resolve("report.md")));
    }
}
