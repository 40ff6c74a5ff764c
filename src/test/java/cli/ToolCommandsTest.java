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
