package distributed;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import renderer.ImageWriter;
import sceneio.SceneFileException;
import sceneio.SceneLoader;

/** Small scene files for the Spark tests, written into a test's temporary folder. */
final class TestScenes {
    private TestScenes() {}

    /**
     * scenes/soft-shadows.json at {@code width x height}, with its OBJ meshes in a subfolder ({@code scene/soft.json}
     * names {@code models/*.obj}), so the scene travels with files of its own folder tree (files outside it are
     * refused, docs/CLI.md, "Security model"). Random sampling everywhere: jittered anti-aliasing and adaptive soft
     * shadows.
     */
    static Path softShadows(Path dir, int width, int height) throws IOException {
        Path models = Files.createDirectories(dir.resolve("scene/models"));
        for (String obj : List.of("icosphere.obj", "cube.obj")) {
            Files.copy(Path.of("scenes/models", obj), models.resolve(obj));
        }
        String text = Files.readString(Path.of("scenes/soft-shadows.json"))
                .replace("\"width\": 480", "\"width\": " + width)
                .replace("\"height\": 320", "\"height\": " + height)
                .replace("\"samples\": 36", "\"samples\": 9");
        Path scene = Files.createDirectories(dir.resolve("scene")).resolve("soft.json");
        Files.writeString(scene, text);
        return scene;
    }

    /** The image of {@code Camera.renderImage()} for the scene file, on this machine. */
    static ImageWriter renderLocally(Path scene) throws SceneFileException {
        return SceneLoader.load(scene).camera().renderImage().getImage();
    }

    /** The pixels that differ between two images of the same size, as "x,y" (empty when bit-identical). */
    static List<String> differences(ImageWriter expected, ImageWriter actual) {
        List<String> diff = new ArrayList<>();
        for (int y = 0; y < expected.getNy(); y++) {
            for (int x = 0; x < expected.getNx(); x++) {
                // Color.equals compares the doubles exactly
                if (!expected.getPixel(x, y).equals(actual.getPixel(x, y))) diff.add(x + "," + y);
            }
        }
        return diff;
    }
}
