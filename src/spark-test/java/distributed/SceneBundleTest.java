package distributed;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import renderer.ImageWriter;
import sceneio.SceneFileException;
import sceneio.SceneLoader;

/**
 * A scene bundle carries the scene file's text and its OBJ files (also from outside the scene's folder), so an
 * executor without the files builds the same scene; a bad scene fails when bundling, on the driver.
 */
class SceneBundleTest {
    @TempDir
    Path dir;

    private static SceneBundle travel(SceneBundle bundle) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(bundle);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            return (SceneBundle) in.readObject();
        }
    }

    @Test
    void theObjFilesTravelWithTheSceneAndTheImageIsTheSame() throws Exception {
        Path scene = TestScenes.softShadows(dir, 24, 16);
        ImageWriter local = TestScenes.renderLocally(scene);
        SceneBundle bundle = SceneBundle.read(scene);
        assertEquals(List.of("models/icosphere.obj", "models/cube.obj"), bundle.objFiles());
        assertEquals("soft-shadows", bundle.sceneName());
        assertEquals(24, bundle.width());
        assertEquals(16, bundle.height());
        // The executor has no copy of the files: delete them before loading the bundle.
        Files.delete(dir.resolve("scene/models/icosphere.obj"));
        Files.delete(dir.resolve("scene/models/cube.obj"));
        Files.delete(scene);
        ImageWriter remote = travel(bundle)
                .load(UnaryOperator.identity())
                .camera()
                .renderImage()
                .getImage();
        assertEquals(List.of(), TestScenes.differences(local, remote));
    }

    @Test
    void aSceneWithoutObjFilesCarriesOnlyItsText() throws Exception {
        Path scene = Files.writeString(dir.resolve("aa.json"), Files.readString(Path.of("scenes/aa-edges.json")));
        SceneBundle bundle = SceneBundle.read(scene);
        assertEquals(List.of(), bundle.objFiles());
        assertEquals(Files.readString(scene).length(), bundle.size());
        assertEquals(
                SceneLoader.load(scene).scene().getName(),
                travel(bundle).load(UnaryOperator.identity()).scene().getName());
    }

    @Test
    void aBadSceneFailsWhenBundled() throws Exception {
        Path scene = Files.writeString(dir.resolve("bad.json"), "{\"render\": {\"width\": 4, \"height\": 4}}");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneBundle.read(scene));
        assertEquals(
                assertThrows(SceneFileException.class, () -> SceneLoader.load(scene))
                        .getMessage(),
                e.getMessage());
    }

    /** A scene from someone else cannot ship files from outside its folder tree to the cluster (docs/CLI.md). */
    @Test
    void aSceneNamingFilesOutsideItsFolderIsRefusedOnTheDriver() throws Exception {
        Path scene = TestScenes.softShadows(dir, 8, 8);
        Files.writeString(scene, Files.readString(scene).replace("\"models/", "\"../../models/"));
        Files.createDirectories(dir.resolveSibling("models"));
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneBundle.read(scene));
        assertTrue(e.getMessage().contains("not found") || e.getMessage().contains("outside"), e.getMessage());
    }
}
