package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import sceneio.model.SceneDocument;

/**
 * Fuzzes the scene loader: whatever the bytes, loading gives a scene or a {@link SceneFileException}; any other
 * exception (or a document that does not survive writing and reading back) fails. OBJ paths resolve against the
 * test resources, so mutated meshes reach the OBJ reader too. {@code mvn test} replays the committed inputs in
 * {@code src/test/resources/sceneio/SceneLoaderFuzzTestInputs/}; {@code JAZZER_FUZZ=1} fuzzes (docs/CLI.md).
 */
class SceneLoaderFuzzTest {
    private static final Path OBJ_FOLDER = Path.of("src/test/resources/sceneio");

    @FuzzTest(maxDuration = "5m")
    void sceneJson(byte[] data) {
        String json = new String(data, StandardCharsets.UTF_8);
        LoadedScene loaded;
        try {
            loaded = SceneLoader.load(json, "fuzz.json", OBJ_FOLDER);
        } catch (SceneFileException expected) {
            return; // the declared error
        }
        SceneDocument document = loaded.document();
        try {
            assertEquals(document, SceneLoader.parse(SceneWriter.toJson(document), "written.json"));
        } catch (SceneFileException e) {
            throw new AssertionError("a loaded document must read back after writing: " + e.getMessage(), e);
        }
    }
}
