package distributed;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cli.RaytracerCli;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The Spark command line's bad input: exit code 2 and one error line before Spark starts; for a bad scene file,
 * exactly the line the {@code raytracer render} CLI prints for the same file.
 */
class SparkCommandTest {
    private static final String VALID = """
            {
              "camera": {"location": [0, -10, 0], "lookAt": [0, 0, 0], "up": [0, 0, 1], "vpDistance": 10,
                         "vpWidth": 4, "vpHeight": 4},
              "render": {"width": 4, "height": 4},
              "geometries": [
                {"type": "sphere", "center": [0, 0, 0], "radius": 1}
              ]
            }
            """;

    @TempDir
    static Path dir;

    private static Path valid, path;

    @BeforeAll
    static void writeFiles() throws Exception {
        valid = Files.writeString(dir.resolve("valid.json"), VALID);
        path = Files.writeString(
                dir.resolve("path.json"),
                "{\"keyframes\": [{\"frame\": 0, \"location\": [0, -10, 0], \"target\": [0, 0, 0]},"
                        + " {\"frame\": 2, \"location\": [10, -10, 0], \"target\": [0, 0, 0]}]}");
    }

    /** Exit code and stderr of a command line. */
    private record Result(int code, String err) {}

    private static Result spark(String... args) {
        StringWriter err = new StringWriter();
        int code = SparkRenderMain.run(args, new PrintWriter(new StringWriter(), true), new PrintWriter(err, true));
        return new Result(code, err.toString());
    }

    private static Result cli(String... args) {
        StringWriter err = new StringWriter();
        int code = RaytracerCli.run(args, new PrintWriter(new StringWriter(), true), new PrintWriter(err, true));
        return new Result(code, err.toString());
    }

    static Stream<Arguments> badScenes() {
        return Stream.of(
                Arguments.of("missing file", null),
                Arguments.of("malformed JSON", VALID.replace("\"width\": 4,", "\"width\": 4,,")),
                Arguments.of("unknown field", VALID.replace("\"vpDistance\"", "\"vpDist\"")),
                Arguments.of("negative radius", VALID.replace("\"radius\": 1", "\"radius\": -2")),
                Arguments.of(
                        "missing OBJ",
                        VALID.replace("\"type\": \"sphere\"", "\"type\": \"mesh\", \"file\": \"x.obj\"")
                                .replace(", \"center\": [0, 0, 0], \"radius\": 1", "")));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badScenes")
    void aBadSceneGivesExactlyTheCliMessage(String what, String json) throws Exception {
        Path scene = dir.resolve(what.replace(' ', '-') + ".json");
        if (json != null) Files.writeString(scene, json);
        Result render =
                cli("render", scene.toString(), "-o", dir.resolve("cli.png").toString());
        assertEquals(2, render.code(), render.err());
        assertTrue(render.err().startsWith("error: " + scene), render.err());
        assertEquals(1, render.err().lines().count(), render.err());
        assertEquals(
                render,
                spark("tiles", scene.toString(), "-o", dir.resolve("tiles.png").toString()));
        assertEquals(render, spark("frames", scene.toString(), "--path", path.toString()));
    }

    @Test
    void aBadPathIsReportedLikeABadScene() throws Exception {
        Path bad = Files.writeString(dir.resolve("bad-path.json"), "{\"keyframes\": [{\"frame\": 1}]}");
        Result r = spark("frames", valid.toString(), "--path", bad.toString());
        assertEquals(2, r.code());
        assertEquals("error: " + bad + ":1:16: $.keyframes[0]: missing \"location\": the camera position\n", r.err());
    }

    @Test
    void badOverridesGiveTheCliMessage() {
        for (String[] option : new String[][] {{"--width", "0"}, {"--samples", "2000000"}, {"--bvh", "maybe"}}) {
            Result render = cli(
                    "render",
                    valid.toString(),
                    option[0],
                    option[1],
                    "-o",
                    dir.resolve("o.png").toString());
            assertEquals(2, render.code(), render.err());
            Result tiles = spark("tiles", valid.toString(), option[0], option[1]);
            Result frames = spark("frames", valid.toString(), "--path", path.toString(), option[0], option[1]);
            // picocli's own rejections (an unknown enum value) end with the command's usage, which differs.
            assertEquals(render.err().lines().findFirst(), tiles.err().lines().findFirst(), option[0]);
            assertEquals(render.err().lines().findFirst(), frames.err().lines().findFirst(), option[0]);
            assertEquals(2, tiles.code());
            assertEquals(2, frames.code());
        }
    }

    @Test
    void badTilesAreReportedBeforeSparkStarts() {
        Result zero = spark("tiles", valid.toString(), "--tiles", "0");
        assertEquals(new Result(2, "error: --tiles must be at least 1, but was 0\n"), zero);
        Result typo = spark("tiles", valid.toString(), "--tiles", "4by4");
        assertEquals(2, typo.code());
        assertTrue(typo.err().startsWith("error: --tiles must be COLSxROWS (e.g. 4x4) or a tile count"), typo.err());
        Result tooMany = spark("tiles", valid.toString(), "--tiles", "5x1");
        assertEquals(2, tooMany.code());
        assertTrue(tooMany.err().contains("cannot split a 4 x 4 image into 5x1 tiles"), tooMany.err());
    }

    @Test
    void badOutputsAreReportedBeforeSparkStarts() {
        Result noPng =
                spark("tiles", valid.toString(), "-o", dir.resolve("out.jpg").toString());
        assertEquals(2, noPng.code());
        assertTrue(noPng.err().contains("must be a .png file name"), noPng.err());
        Result noNumber = spark(
                "frames",
                valid.toString(),
                "--path",
                path.toString(),
                "-o",
                dir.resolve("f.png").toString());
        assertEquals(2, noNumber.code());
        assertTrue(noNumber.err().contains("must hold one frame number, %d or %04d"), noNumber.err());
        Result missingFolder = spark(
                "frames",
                valid.toString(),
                "--path",
                path.toString(),
                "-o",
                dir.resolve("no/f-%d.png").toString());
        assertEquals(2, missingFolder.code());
        assertTrue(missingFolder.err().contains("does not exist"), missingFolder.err());
    }

    @Test
    void withoutAMasterNothingStarts() {
        assertNull(System.getProperty("spark.master"), "the test JVM names no master");
        Result r = spark(
                "tiles", valid.toString(), "-o", dir.resolve("nomaster.png").toString());
        assertEquals(2, r.code());
        assertTrue(r.err().startsWith("error: no Spark master: run through spark-submit"), r.err());
        assertFalse(Files.exists(dir.resolve("nomaster.png")));
    }

    @Test
    void withoutASubcommandTheUsageIsShown() {
        Result r = spark();
        assertEquals(2, r.code());
        assertTrue(r.err().contains("a subcommand is required: tiles or frames"), r.err());
        assertTrue(r.err().contains("Usage: raytracer-spark"), r.err());
    }
}
