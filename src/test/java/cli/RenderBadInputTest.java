package cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each kind of bad scene, through the command line: exit code 2, one "error:" line naming the file, the line and
 * column, the JSON path and what is wrong, and the old image at the output path untouched.
 */
class RenderBadInputTest {
    private static final String VALID = """
            {
              "camera": {"location": [0, -10, 0], "lookAt": [0, 0, 0], "vpDistance": 10, "vpWidth": 4,
                         "vpHeight": 4},
              "render": {"width": 4, "height": 4},
              "geometries": [
                {"type": "sphere", "center": [0, 0, 0], "radius": 1}
              ]
            }
            """;
    private static final String SPHERE = "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}";

    static Stream<Arguments> badScenes() {
        return Stream.of(
                Arguments.of(
                        "malformed JSON",
                        VALID.replace("\"width\": 4,", "\"width\": 4,,"),
                        ":4:25: $.render:" + " malformed JSON"),
                Arguments.of(
                        "unknown field",
                        VALID.replace("\"vpDistance\"", "\"vpDist\""),
                        ":2:60: $.camera.vpDist:" + " unknown field"),
                Arguments.of(
                        "wrong type",
                        VALID.replace("\"radius\": 1", "\"radius\": \"1\""),
                        ":6:45:" + " $.geometries[0].radius: wrong type: expected a number"),
                Arguments.of(
                        "missing field",
                        VALID.replace("\"center\": [0, 0, 0], ", ""),
                        ":6:5: $.geometries[0]:" + " missing required field \"center\""),
                Arguments.of(
                        "negative radius",
                        VALID.replace("\"radius\": 1", "\"radius\": -2"),
                        ":6:45:" + " $.geometries[0].radius: sphere radius must be positive"),
                Arguments.of(
                        "zero direction",
                        VALID.replace("\"lookAt\": [0, 0, 0]", "\"direction\": [0, 0, 0]"),
                        ":2:39: $.camera.direction: vector must not be zero"),
                Arguments.of(
                        "polygon not planar",
                        VALID.replace(
                                SPHERE, "{\"type\": \"polygon\", \"vertices\": [[0,0,0], [1,0,0], [1,1,1], [0,1,0]]}"),
                        ":6:25: $.geometries[0].vertices: polygon is not planar"),
                Arguments.of(
                        "missing OBJ file",
                        VALID.replace(SPHERE, "{\"type\": \"mesh\", \"file\": \"nope.obj\"}"),
                        ":6:22: $.geometries[0].file: OBJ file \"nope.obj\" not found"),
                Arguments.of(
                        "OBJ index out of range",
                        VALID.replace(SPHERE, "{\"type\": \"mesh\", \"file\": \"big.obj\"}"),
                        ":6:22: $.geometries[0].file: OBJ file "),
                Arguments.of(
                        "OBJ index zero",
                        VALID.replace(SPHERE, "{\"type\": \"mesh\", \"file\": \"zero.obj\"}"),
                        ":6:22: $.geometries[0].file: OBJ file "),
                Arguments.of(
                        "target error and time budget",
                        VALID.replace("\"height\": 4}", "\"height\": 4, \"targetError\": 1, \"timeBudget\": 2}"),
                        ":4:57: $.render.timeBudget: give either \"targetError\" or \"timeBudget\", not both"),
                Arguments.of(
                        "negative target error",
                        VALID.replace("\"height\": 4}", "\"height\": 4, \"targetError\": -1}"),
                        ":4:39: $.render.targetError: target error must be in (0, 255] display steps"),
                Arguments.of(
                        "no camera",
                        VALID.replaceFirst("\"camera\": \\{[^}]*},", ""),
                        ":1:1: $: the scene has" + " no camera"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badScenes")
    void badSceneExitsTwoWithThePlaceAndKeepsTheOldImage(String kind, String json, String place, @TempDir Path dir)
            throws IOException {
        Files.writeString(dir.resolve("big.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        Files.writeString(dir.resolve("zero.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
        Path scene = Files.writeString(dir.resolve("scene.json"), json);
        Path png = Files.write(dir.resolve("old.png"), new byte[] {7});
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = RaytracerCli.run(
                new String[] {"render", scene.toString(), "-o", png.toString()},
                new PrintWriter(out, true),
                new PrintWriter(err, true));
        assertEquals(ExitCodes.BAD_INPUT, code, kind + ": " + err);
        assertTrue(err.toString().startsWith("error: " + scene + place), kind + ": " + err);
        assertEquals(1, err.toString().strip().lines().count(), "one line: " + err);
        assertArrayEquals(new byte[] {7}, Files.readAllBytes(png), "the old image is untouched");
        assertEquals("", out.toString());
    }

    @org.junit.jupiter.api.Test
    void progressiveOptionsRenderAndPrintTheirPredictionOrAreRefused(@TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("scene.json"), VALID);
        Path png = dir.resolve("out.png");
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = RaytracerCli.run(
                new String[] {"render", scene.toString(), "-o", png.toString(), "--target-error", "2"},
                new PrintWriter(out, true),
                new PrintWriter(err, true));
        assertEquals(ExitCodes.OK, code, err.toString());
        assertTrue(out.toString().contains("progressive: target RMSE 2.00, predicted RMSE"), out.toString());
        StringWriter err2 = new StringWriter();
        int both = RaytracerCli.run(
                new String[] {
                    "render", scene.toString(), "-o", png.toString(), "--target-error", "2", "--time-budget", "3"
                },
                new PrintWriter(new StringWriter(), true),
                new PrintWriter(err2, true));
        assertEquals(ExitCodes.BAD_INPUT, both);
        assertTrue(err2.toString().contains("give either --target-error or --time-budget, not both"), err2.toString());
    }
}
