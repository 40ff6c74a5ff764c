package app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import renderer.Camera;
import renderer.ImageWriter;
import sceneio.LoadedScene;
import sceneio.SceneFileException;
import sceneio.SceneLoader;
import sceneio.model.SceneDocument;

/**
 * {@code scenes/street.json}, the README's main job, is the street scene of {@link StreetSceneFile}: loaded and
 * rendered small, it gives exactly the pixels of the Java scene. When {@link StreetScene} changes, this fails until
 * the file is written again ({@code mvn -q compile exec:java -Dexec.mainClass=app.StreetSceneFile}).
 */
class StreetSceneFileTest {
    private static final int W = 64, H = 40;

    @Test
    void theSceneFileRendersExactlyTheJavaScene() throws SceneFileException {
        Path file = Path.of("scenes", "street.json");
        SceneDocument document = SceneLoader.read(file);
        assertEquals(StreetSceneFile.WIDTH, document.render().width());
        assertEquals(StreetSceneFile.HEIGHT, document.render().height());
        // Same view plane aspect (16:10), so only the resolution changes.
        LoadedScene loaded =
                SceneLoader.build(document.withRender(document.render().withSize(W, H)), file);
        assertTrue(loaded.warnings().isEmpty(), loaded.warnings().toString());

        Camera fromFile = loaded.camera().renderImage();
        StreetScene street = StreetSceneFile.street();
        Camera fromJava = StreetSceneFile.camera(street, W, H).build().renderImage();
        assertArrayEquals(pixels(fromJava.getImage()), pixels(fromFile.getImage()));
        assertEquals(
                fromJava.getLastStatistics().rays().shadow,
                fromFile.getLastStatistics().rays().shadow,
                "same lights, radii and sample counts");
    }

    private static int[] pixels(ImageWriter image) {
        return image.toBufferedImage().getRGB(0, 0, W, H, null, 0, W);
    }
}
