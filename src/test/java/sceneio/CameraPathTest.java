package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import renderer.Camera;
import sceneio.model.Interpolation;
import sceneio.model.SceneDocument;
import sceneio.model.Vec3;

/**
 * Camera path files: keyframes are hit exactly, linear and smooth motion in between, the frame count, aiming a
 * scene at a pose, and bad files reported with file:line:column, JSON path and (for impossible poses) the frame.
 */
class CameraPathTest {
    private static final String SCENE = """
            {
              "camera": {"location": [0, -10, 0], "lookAt": [0, 0, 0], "up": [0, 0, 1], "vpDistance": 10,
                         "vpWidth": 4, "vpHeight": 3},
              "render": {"width": 8, "height": 6}
            }
            """;

    @TempDir
    Path dir;

    private SceneDocument scene() throws SceneFileException {
        return SceneLoader.parse(SCENE, "scene.json");
    }

    private CameraPath load(String json) throws IOException, SceneFileException {
        Path file = dir.resolve("path.json");
        Files.writeString(file, json);
        return CameraPathLoader.load(file, scene());
    }

    private SceneFileException error(String json) throws IOException {
        Path file = dir.resolve("path.json");
        Files.writeString(file, json);
        return assertThrows(SceneFileException.class, () -> CameraPathLoader.load(file, scene()));
    }

    private static final String THREE_KEYS = """
            {
              "interpolation": "%s",
              "keyframes": [
                {"frame": 0, "location": [0, -10, 0], "target": [0, 0, 0]},
                {"frame": 4, "location": [10, -10, 2], "target": [1, 0, 0]},
                {"frame": 6, "location": [10, 0, 4], "target": [1, 1, 0]}
              ]
            }
            """;

    @Test
    void framesRunFromZeroToTheLastKeyframe() throws Exception {
        CameraPath path = load(THREE_KEYS.formatted("linear"));
        assertEquals(7, path.frameCount());
        assertThrows(IllegalArgumentException.class, () -> path.pose(7));
        assertThrows(IllegalArgumentException.class, () -> path.pose(-1));
    }

    @Test
    void keyframesAreHitExactlyByBothInterpolations() throws Exception {
        for (String kind : new String[] {"linear", "smooth"}) {
            CameraPath path = load(THREE_KEYS.formatted(kind));
            assertEquals(new Vec3(0, -10, 0), path.pose(0).location(), kind);
            assertEquals(new Vec3(10, -10, 2), path.pose(4).location(), kind);
            assertEquals(new Vec3(1, 0, 0), path.pose(4).target(), kind);
            assertEquals(new Vec3(10, 0, 4), path.pose(6).location(), kind);
            assertEquals(new Vec3(1, 1, 0), path.pose(6).target(), kind);
        }
    }

    @Test
    void linearMovesAtConstantSpeedWithinASegment() throws Exception {
        CameraPath path = load(THREE_KEYS.formatted("linear"));
        assertEquals(Interpolation.LINEAR, path.getInterpolation());
        assertEquals(new Vec3(5, -10, 1), path.pose(2).location());
        assertEquals(new Vec3(0.5, 0, 0), path.pose(2).target());
        assertEquals(new Vec3(10, -5, 3), path.pose(5).location());
    }

    @Test
    void smoothIsTheCatmullRomSpline() throws Exception {
        CameraPath path = load(THREE_KEYS.formatted("smooth"));
        // Frame 2, halfway through the first segment (span 4): h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8; the tangent
        // at key 0 is one-sided, (10, 0, 2) / 4 per frame, at key 1 central, (10, 10, 4) / 6 per frame.
        double x = 0.5 * 0 + 0.125 * 4 * 10 / 4.0 + 0.5 * 10 - 0.125 * 4 * 10 / 6.0;
        double y = 0.5 * -10 + 0 + 0.5 * -10 - 0.125 * 4 * 10 / 6.0;
        Vec3 mid = path.pose(2).location();
        assertEquals(x, mid.x(), 1e-12);
        assertEquals(y, mid.y(), 1e-12);
        assertNotEquals(-10, mid.y(), "the spline bends where the straight line would not");
    }

    @Test
    void smoothVelocityIsContinuousThroughAKeyframe() throws Exception {
        String keys = """
                {"interpolation": "smooth", "keyframes": [
                  {"frame": 0, "location": [0, -10, 0], "target": [0, 0, 0]},
                  {"frame": 100, "location": [10, -10, 0], "target": [0, 0, 0]},
                  {"frame": 200, "location": [10, 0, 0], "target": [0, 0, 0]}]}
                """;
        CameraPath smooth = load(keys);
        CameraPath linear = load(keys.replace("smooth", "linear"));
        // Velocity just before and after frame 100: the spline's changes by its acceleration over one frame
        // (about 0.002), the lines' turns by 90 degrees (0.1 in x goes to 0, 0 in y goes to 0.1).
        Vec3 a = smooth.pose(99).location();
        Vec3 b = smooth.pose(100).location();
        Vec3 c = smooth.pose(101).location();
        assertEquals(b.x() - a.x(), c.x() - b.x(), 0.01);
        assertEquals(b.y() - a.y(), c.y() - b.y(), 0.01);
        Vec3 la = linear.pose(99).location(), lc = linear.pose(101).location();
        assertEquals(0.1, 10 - la.x(), 1e-12);
        assertEquals(0.1, lc.y() + 10, 1e-12);
    }

    @Test
    void aSingleKeyframeIsAStill() throws Exception {
        CameraPath path = load("{\"keyframes\": [{\"frame\": 0, \"location\": [1, 2, 3], \"target\": [0, 0, 0]}]}");
        assertEquals(1, path.frameCount());
        assertEquals(Interpolation.LINEAR, path.getInterpolation(), "the default");
    }

    @Test
    void aimingMovesOnlyTheCamerasLocationAndTarget() throws Exception {
        CameraPath path = load(THREE_KEYS.formatted("linear"));
        SceneDocument aimed = CameraPath.aim(scene(), path.pose(5));
        assertEquals(new Vec3(10, -5, 3), aimed.camera().location());
        assertEquals(new Vec3(1, 0.5, 0), aimed.camera().lookAt());
        assertEquals(scene().camera().up(), aimed.camera().up());
        assertEquals(scene().camera().vpWidth(), aimed.camera().vpWidth());
        assertEquals(scene().render(), aimed.render());
        Camera camera = SceneLoader.build(aimed, "scene.json", dir, null).camera();
        assertEquals(8, camera.getNx());
        assertEquals(0, camera.constructRay(8, 6, 0, 0).getHead().distance(new primitives.Point(10, -5, 3)), 1e-12);
    }

    @Test
    void theShippedPathLoadsOnItsScene() throws Exception {
        CameraPath path = CameraPathLoader.load(
                Path.of("scenes/paths/soft-shadows-orbit.json"), SceneLoader.read(Path.of("scenes/soft-shadows.json")));
        assertEquals(24, path.frameCount());
        assertEquals(Interpolation.SMOOTH, path.getInterpolation());
        assertEquals(new Vec3(300, 0, 120), path.pose(23).location());
    }

    @Test
    void badFilesNameThePlaceAndWhatIsAllowed() throws IOException {
        assertEquals(
                dir.resolve("path.json") + ":1:1: $.keyframes: a camera path needs keyframes: \"keyframes\":"
                        + " [{\"frame\": 0, \"location\": [x, y, z], \"target\": [x, y, z]}, ...]",
                error("{}").getMessage(),
                "a missing field is placed at the object that lacks it");
        SceneFileException first = error(THREE_KEYS.formatted("linear").replace("\"frame\": 0", "\"frame\": 1"));
        assertTrue(first.getMessage().endsWith("the first keyframe must be frame 0, but was 1"), first.getMessage());
        assertEquals("$.keyframes[0].frame", first.getJsonPath());
        assertEquals(4, first.getLine());
        SceneFileException order = error(THREE_KEYS.formatted("linear").replace("\"frame\": 6", "\"frame\": 4"));
        assertEquals("keyframes must be in increasing frame order, but frame 4 follows frame 4", order.getProblem());
        assertEquals(6, order.getLine());
        SceneFileException unknown = error(THREE_KEYS.formatted("cubic"));
        assertEquals("$.interpolation", unknown.getJsonPath());
        assertTrue(unknown.getProblem().contains("allowed: linear, smooth"), unknown.getProblem());
        SceneFileException typo = error(THREE_KEYS.formatted("linear").replace("\"target\": [1, 0, 0]", "\"tgt\": 1"));
        assertTrue(typo.getProblem().startsWith("unknown field \"tgt\""), typo.getProblem());
        SceneFileException missing = error("{\"keyframes\": [{\"frame\": 0, \"location\": [1, 2, 3]}]}");
        assertEquals("missing \"target\": the point to look at", missing.getProblem());
        SceneFileException tooMany =
                error("{\"keyframes\": [{\"frame\": 0, \"location\": [1, 2, 3], \"target\": [0, 0, 0]},"
                        + " {\"frame\": 1000000, \"location\": [1, 2, 3], \"target\": [0, 0, 0]}]}");
        assertTrue(tooMany.getProblem().startsWith("a path has at most 1000000 frames"), tooMany.getProblem());
        SceneFileException absent =
                assertThrows(SceneFileException.class, () -> CameraPathLoader.load(dir.resolve("no.json"), scene()));
        assertEquals("camera path file not found", absent.getProblem());
    }

    @Test
    void aPoseTheCameraCannotTakeNamesTheFrame() throws IOException {
        // Frame 1 of 0..2 passes through the target: the camera would look at its own location.
        SceneFileException through = error("""
                {"keyframes": [
                  {"frame": 0, "location": [0, -10, 1], "target": [0, 0, 1]},
                  {"frame": 2, "location": [0, 10, 1], "target": [0, 0, 1]}]}
                """);
        assertEquals("$.keyframes[0]", through.getJsonPath());
        assertTrue(
                through.getProblem()
                        .startsWith("at frame 1 the scene's camera cannot take the pose location [0.0, 0.0, 1.0],"
                                + " target [0.0, 0.0, 1.0]: the camera cannot look at its own location"),
                through.getProblem());
        // Frame 2 looks straight down, along the scene's up (0, 0, 1).
        SceneFileException alongUp = error("""
                {"keyframes": [
                  {"frame": 0, "location": [0, -10, 10], "target": [0, 0, 0]},
                  {"frame": 2, "location": [0, 0, 10], "target": [0, 0, 0]}]}
                """);
        assertEquals("$.keyframes[1]", alongUp.getJsonPath());
        assertTrue(alongUp.getProblem().startsWith("at frame 2 "), alongUp.getProblem());
        assertTrue(alongUp.getProblem().contains("parallel"), alongUp.getProblem());
    }
}
