package sceneio;

import com.fasterxml.jackson.core.JsonProcessingException;
import java.nio.file.Path;
import java.util.List;
import sceneio.model.CameraPathDocument;
import sceneio.model.Interpolation;
import sceneio.model.KeyframeDocument;
import sceneio.model.SceneDocument;
import sceneio.model.Vec3;

/**
 * Reads camera path files (docs/SPARK.md) as strictly as scene files: unknown fields, wrong types and bad values
 * are {@link SceneFileException}s naming the path file, line:column and JSON path. Every frame's pose is also
 * tried on the scene's camera, so a pose the camera cannot take (looking at its own location, or along its
 * {@code up}) is reported here, before anything is rendered, naming the frame.
 *
 * <pre>{@code
 * {
 *   "interpolation": "smooth",
 *   "keyframes": [
 *     { "frame": 0,  "location": [0, -420, 160], "target": [0, 0, 40] },
 *     { "frame": 47, "location": [420, 0, 160],  "target": [0, 0, 40] }
 *   ]
 * }
 * }</pre>
 */
public final class CameraPathLoader {
    /** Most frames a path may have: far beyond a film shot, small enough to check every pose up front. */
    public static final int MAX_FRAMES = 1_000_000;

    private CameraPathLoader() {}

    /**
     * Reads a camera path and checks every pose on the scene's camera.
     *
     * @param scene the scene the path moves through, already loaded without error
     * @param file the camera path JSON file
     * @return the checked camera path
     * @throws SceneFileException if the file cannot be read, is not a valid camera path, or a pose cannot be taken by
     *     the scene's camera
     */
    public static CameraPath load(Path file, SceneDocument scene) throws SceneFileException {
        String name = file.toString();
        String text = SceneLoader.text(file, "camera path file");
        CameraPathDocument d;
        try {
            d = SceneJson.MAPPER.readValue(text, CameraPathDocument.class);
        } catch (JsonProcessingException e) {
            throw JsonErrors.translate(name, text, e);
        }
        JsonPath root = JsonPath.ROOT;
        if (d == null) throw fail(name, text, root, "expected a JSON object holding the camera path, but found null");
        if (d.version() != null && d.version() != 1) {
            throw fail(name, text, root.field("version"), "unsupported format version " + d.version() + "; allowed: 1");
        }
        List<KeyframeDocument> keys = d.keyframes();
        JsonPath at = root.field("keyframes");
        if (keys == null || keys.isEmpty()) {
            throw fail(
                    name,
                    text,
                    at,
                    "a camera path needs keyframes: \"keyframes\": [{\"frame\": 0, \"location\": [x, y, z],"
                            + " \"target\": [x, y, z]}, ...]");
        }
        int[] frames = new int[keys.size()];
        Vec3[] locations = new Vec3[keys.size()], targets = new Vec3[keys.size()];
        for (int k = 0; k < keys.size(); k++) {
            JsonPath kp = at.index(k);
            KeyframeDocument key = keys.get(k);
            if (key == null) throw fail(name, text, kp, "null is not a keyframe: give {\"frame\": n, ...}");
            if (key.frame() == null) throw fail(name, text, kp, "missing \"frame\": the keyframe's frame number");
            if (key.location() == null) throw fail(name, text, kp, "missing \"location\": the camera position");
            if (key.target() == null) throw fail(name, text, kp, "missing \"target\": the point to look at");
            int frame = key.frame();
            if (k == 0 && frame != 0) {
                throw fail(name, text, kp.field("frame"), "the first keyframe must be frame 0, but was " + frame);
            }
            if (k > 0 && frame <= frames[k - 1]) {
                throw fail(
                        name,
                        text,
                        kp.field("frame"),
                        "keyframes must be in increasing frame order, but frame " + frame + " follows frame "
                                + frames[k - 1]);
            }
            if (frame >= MAX_FRAMES) {
                throw fail(
                        name,
                        text,
                        kp.field("frame"),
                        "a path has at most " + MAX_FRAMES + " frames (0.." + (MAX_FRAMES - 1)
                                + "), but this keyframe is frame " + frame);
            }
            frames[k] = frame;
            locations[k] = key.location();
            targets[k] = key.target();
        }
        Interpolation interpolation = d.interpolation() == null ? Interpolation.LINEAR : d.interpolation();
        CameraPath path = new CameraPath(interpolation, frames, locations, targets);
        checkPoses(name, text, path, frames, scene);
        return path;
    }

    /**
     * Builds the scene's camera (and nothing else of the scene) in every pose, so the errors of the scene loader
     * are found per frame and reported at the keyframe that starts the frame's segment.
     */
    private static void checkPoses(String name, String text, CameraPath path, int[] frames, SceneDocument scene)
            throws SceneFileException {
        SceneDocument cameraOnly = new SceneDocument(
                scene.version(),
                scene.name(),
                scene.seed(),
                null,
                null,
                scene.camera(),
                scene.render(),
                null,
                null,
                null,
                null);
        int key = 0;
        for (int frame = 0; frame < path.frameCount(); frame++) {
            if (key + 1 < frames.length && frames[key + 1] == frame) key++;
            try {
                SceneLoader.build(CameraPath.aim(cameraOnly, path.pose(frame)), name, Path.of(""), null);
            } catch (SceneFileException e) {
                throw fail(
                        name,
                        text,
                        JsonPath.ROOT.field("keyframes").index(key),
                        "at frame " + frame + " the scene's camera cannot take the pose " + path.pose(frame) + ": "
                                + e.getProblem());
            }
        }
    }

    private static SceneFileException fail(String name, String text, JsonPath at, String problem) {
        return new DocumentValues(name, () -> text).fail(at, problem);
    }
}
