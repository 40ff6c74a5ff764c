package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every kind of bad scene file is a {@link SceneFileException} whose message names the file, the place (line:column
 * and JSON path) and what is allowed.
 */
class SceneBadInputTest {
    private static final Path RESOURCES = Path.of("src/test/resources/sceneio");

    /** A valid scene; each test breaks one thing in it. */
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

    private static SceneFileException error(String json) {
        return assertThrows(SceneFileException.class, () -> SceneLoader.load(json, "bad.json", RESOURCES));
    }

    /** Columns point at the field's name (or, for a missing field, at the object that lacks it). */
    private static void assertMessage(String expected, SceneFileException e) {
        assertEquals(expected, e.getMessage());
    }

    @Test
    void theValidBaseLoads() throws SceneFileException {
        assertEquals(
                1,
                SceneLoader.load(VALID, "ok.json", RESOURCES)
                        .scene()
                        .geometries
                        .getMembers()
                        .size());
    }

    @Test
    void malformedJsonReportsLineAndColumn() {
        SceneFileException e = error(VALID.replace("\"vpWidth\": 4,", "\"vpWidth\": 4,,"));
        assertEquals(2, e.getLine());
        assertEquals(91, e.getColumn()); // the second comma
        assertTrue(
                e.getMessage().startsWith("bad.json:2:91: $.camera: malformed JSON: Unexpected character (','"),
                e.getMessage());
        SceneFileException unterminated = error("{\"name\": \"x");
        assertTrue(unterminated.getMessage().startsWith("bad.json:1:"), unterminated.getMessage());
        assertTrue(unterminated.getMessage().contains("malformed JSON"), unterminated.getMessage());
        assertMessage("bad.json:1: $: the file is empty: expected a JSON object holding the scene", error(""));
    }

    @Test
    void unknownFieldsListWhatIsAllowed() {
        assertMessage(
                "bad.json:4:14: $.render.widht: unknown field \"widht\"; allowed fields here: adaptiveShadows,"
                        + " antiAliasing, bvh, glossySamples, height, lightCutoff, maxLevel, shadowPattern, targetError,"
                        + " threads, timeBudget, width",
                error(VALID.replace("\"width\": 4", "\"widht\": 4")));
        assertMessage(
                "bad.json:6:5: $.geometries[0]: unknown geometry type \"sphear\"; allowed: sphere, plane, triangle,"
                        + " polygon, tube, cylinder, mesh, group, instance",
                error(VALID.replace("\"sphere\"", "\"sphear\"")));
    }

    @Test
    void wrongTypesSayWhatWasExpectedAndFound() {
        assertMessage(
                "bad.json:4:14: $.render.width: wrong type: expected an integer, but found a string (\"4\")",
                error(VALID.replace("\"width\": 4", "\"width\": \"4\"")));
        assertMessage(
                "bad.json:6:24: $.geometries[0].center: expected [x, y, z] (an array of 3 numbers), but it has 2",
                error(VALID.replace("[0, 0, 0], \"radius\"", "[0, 0], \"radius\"")));
        assertMessage(
                "bad.json:6:45: $.geometries[0].radius: wrong type: expected a number, but found a boolean",
                error(VALID.replace("\"radius\": 1", "\"radius\": true")));
        assertMessage(
                "bad.json:2:39: $.camera.lookAt: expected [x, y, z] (an array of 3 numbers), but element 0 is a"
                        + " string",
                error(VALID.replace("\"lookAt\": [0, 0, 0]", "\"lookAt\": [\"0\", 0, 0]")));
    }

    @Test
    void missingRequiredFieldsAreNamed() {
        assertMessage(
                "bad.json:6:5: $.geometries[0]: missing required field \"radius\"",
                error(VALID.replace(", \"radius\": 1", "")));
        assertMessage(
                "bad.json:4:3: $.render: missing required field \"height\"",
                error(VALID.replace(", \"height\": 4", "")));
    }

    @Test
    void negativeRadiusKeepsTheCoreMessageWithItsPlace() {
        assertMessage(
                "bad.json:6:45: $.geometries[0].radius: sphere radius must be positive and finite, but was -1.0",
                error(VALID.replace("\"radius\": 1", "\"radius\": -1")));
    }

    @Test
    void zeroDirectionIsRejected() {
        String json = VALID.replace(
                "\"render\"",
                "\"lights\": [{\"type\": \"directional\", \"color\": [1, 1, 1], \"direction\": [0, 0, 0]}],\n"
                        + "  \"render\"");
        assertMessage(
                "bad.json:4:58: $.lights[0].direction: vector must not be zero: a zero vector has no direction",
                error(json));
    }

    @Test
    void polygonNotPlanarIsRejected() {
        String json = VALID.replace(
                "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}",
                "{\"type\": \"polygon\", \"vertices\": [[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]]}");
        SceneFileException e = error(json);
        assertTrue(
                e.getMessage().startsWith("bad.json:6:25: $.geometries[0].vertices: polygon is not planar: vertex"),
                e.getMessage());
    }

    @Test
    void unknownMaterialListsTheDefinedOnes() {
        String json = VALID.replace("\"radius\": 1}", "\"radius\": 1, \"material\": \"glas\"}")
                .replace("\"render\"", "\"materials\": {\"glass\": {\"kT\": 1}, \"wood\": {}},\n  \"render\"");
        assertMessage(
                "bad.json:7:58: $.geometries[0].material: unknown material \"glas\"; defined in \"materials\": glass,"
                        + " wood",
                error(json));
    }

    @Test
    void missingObjFileNamesTheFileAndTheJsonPlace() {
        String json = VALID.replace(
                "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}",
                "{\"type\": \"mesh\", \"file\": \"models/none.obj\"}");
        SceneFileException e = error(json);
        assertTrue(
                e.getMessage()
                        .startsWith("bad.json:6:22: $.geometries[0].file: OBJ file \"models/none.obj\" not found"
                                + " (looked for "),
                e.getMessage());
        SceneFileException absolute = error(json.replace("models/none.obj", "/etc/hostname"));
        assertTrue(
                absolute.getMessage().contains("must be a path relative to the scene file's folder"),
                absolute.getMessage());
    }

    @Test
    void objIndicesOutOfRangeOrZeroAreReportedWithObjLineAndJsonPlace() {
        String mesh = "{\"type\": \"mesh\", \"file\": \"%s\"}";
        String sphere = "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}";
        SceneFileException range = error(VALID.replace(sphere, mesh.formatted("bad-index.obj")));
        assertEquals(
                "bad.json:6:22: $.geometries[0].file: OBJ file bad-index.obj:4: face corner '5': vertex index 5 is"
                        + " out of range: 3 defined before this line (allowed are 1..3, or -1..-3 counting back from"
                        + " the latest)",
                range.getMessage());
        SceneFileException zero = error(VALID.replace(sphere, mesh.formatted("zero-index.obj")));
        assertTrue(
                zero.getMessage()
                        .contains("OBJ file zero-index.obj:4: face corner '0': vertex index 0 is invalid:"
                                + " OBJ indices start at 1"),
                zero.getMessage());
    }

    @Test
    void sceneWithoutCameraSaysWhatToAdd() {
        SceneFileException e = error(VALID.replaceFirst("\"camera\": \\{[^}]*},", ""));
        assertMessage(
                "bad.json:1:1: $: the scene has no camera: add \"camera\": {\"location\": [x, y, z], \"lookAt\":"
                        + " [x, y, z], \"vpDistance\": d, \"vpWidth\": w, \"vpHeight\": h}",
                e);
    }

    @Test
    void everySampleCountIsBoundedWithTheSameMessage() {
        String light = "\"lights\": [{\"type\": \"point\", \"color\": [1, 1, 1], \"position\": [0, 0, 5],"
                + " \"radius\": 1, \"samples\": 1000000000}],\n  \"geometries\"";
        assertTrue(error(VALID.replace("\"geometries\"", light))
                .getMessage()
                .endsWith("$.lights[0].samples: light numSamples must be in [1, 1048576], but was 1000000000"));
        assertTrue(error(VALID.replace("\"height\": 4}", "\"height\": 4, \"antiAliasing\": {\"samples\": 2000000}}"))
                .getMessage()
                .endsWith("$.render.antiAliasing.samples: sampleCount must be in [1, 1048576], but was 2000000"));
        assertTrue(error(VALID.replace("\"height\": 4}", "\"height\": 4, \"glossySamples\": 2000000}"))
                .getMessage()
                .endsWith("$.render.glossySamples: sampleCount must be in [1, 1048576], but was 2000000"));
        assertTrue(error(VALID.replace("\"height\": 4}", "\"height\": 4, \"lightCutoff\": -1}"))
                .getMessage()
                .endsWith("$.render.lightCutoff: lightCutoff must be in [0, 255] display steps, but was -1.0"));
    }

    @Test
    void otherValueErrorsAreCaughtBeforeRendering() {
        assertTrue(error(VALID.replace("\"width\": 4", "\"width\": 0"))
                .getMessage()
                .endsWith("$.render.width: width must be >= 1 pixel, but was 0"));
        assertTrue(error(VALID.replace("\"width\": 4, \"height\": 4", "\"width\": 100000, \"height\": 100000"))
                .getMessage()
                .endsWith("image of 100000 x 100000 pixels is too large (at most 2^28 pixels)"));
        assertTrue(error(VALID.replace("\"lookAt\": [0, 0, 0]", "\"lookAt\": [0, -10, 0]"))
                .getMessage()
                .contains("$.camera.lookAt: the camera cannot look at its own location"));
        assertTrue(error(VALID.replace("\"lookAt\"", "\"direction\": [0, 1, 0], \"lookAt\""))
                .getMessage()
                .contains("give exactly one of \"lookAt\""));
        assertTrue(error(VALID.replace("{\n  \"camera\"", "{\n  \"version\": 2, \"camera\""))
                .getMessage()
                .contains("$.version: unsupported format version 2; allowed: 1"));
        assertTrue(error(VALID.replace("\"radius\": 1}", "\"radius\": 1, \"emission\": [-1, 0, 0]}"))
                .getMessage()
                .contains("$.geometries[0].emission: colour channels must be >= 0"));
        assertTrue(error(VALID.replace("\"radius\": 1", "\"radius\": 1e999"))
                .getMessage()
                .contains("sphere radius must be positive and finite, but was Infinity"));
        assertTrue(error("{\"a\": 1, \"a\": 2}").getMessage().contains("Duplicate field 'a'"));
        // Finite values whose difference overflows are still reported at their place.
        assertTrue(
                error(VALID.replace("[0, -10, 0], \"lookAt\": [0, 0, 0]", "[-1e308, 0, 0], \"lookAt\": [1e308, 0, 0]"))
                        .getMessage()
                        .contains("$.camera.lookAt: coordinates must be finite"));
        assertTrue(error(VALID.replace("\"radius\": 1}", "\"radius\": 1e300}"))
                .getMessage()
                .contains("$.geometries[0]"));
        assertTrue(error(VALID + "{}").getMessage().contains("a scene file holds exactly one JSON object"));
    }

    @Test
    void oddMaterialNamesAreQuotedInThePathAndStillLocated() {
        String json = VALID.replace("\"render\"", "\"materials\": {\"a/b~c d\": {\"kD\": -1}},\n  \"render\"");
        assertMessage(
                "bad.json:4:29: $.materials['a/b~c d'].kD: coefficients must be zero or positive (a number or"
                        + " [r, g, b]), but was -1.0",
                error(json));
    }

    @Test
    void unreadableFilesAreSceneFileErrors(@TempDir Path dir) throws Exception {
        Path missing = dir.resolve("missing.json");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneLoader.load(missing));
        assertEquals(missing + ": scene file not found", e.getMessage());
        Path latin1 = Files.write(dir.resolve("latin1.json"), new byte[] {'{', '"', (byte) 0xE9, '"', '}'});
        assertTrue(assertThrows(SceneFileException.class, () -> SceneLoader.load(latin1))
                .getMessage()
                .contains("is not UTF-8 text"));
        assertTrue(assertThrows(SceneFileException.class, () -> SceneLoader.load(dir))
                .getMessage()
                .endsWith("is a folder, not a scene file"));
    }
}
