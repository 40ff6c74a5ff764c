package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicReference;
import renderer.Camera;
import sceneio.model.RenderDocument;
import sceneio.model.SceneDocument;

/**
 * Fuzzes the scene loader: whatever the bytes, loading gives a scene or a {@link SceneFileException}; any other
 * exception (or a document that does not survive writing and reading back) fails. OBJ paths resolve against the
 * test resources, so mutated meshes reach the OBJ reader too. {@link #sceneRenders} also renders whatever
 * loads, at 4 x 3 pixels on one thread under a time limit (cancelled past it), so resource bugs (recursion, sample
 * counts, memory) are reachable: the render must finish or be cancelled, never fail otherwise. {@code mvn test}
 * replays the committed inputs in {@code src/test/resources/sceneio/SceneLoaderFuzzTestInputs/}; {@code
 * JAZZER_FUZZ=1} fuzzes (docs/CLI.md).
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

    /** Wall time a fuzzed render may take before it is cancelled (a legal scene may ask for much work). */
    private static final long RENDER_LIMIT_MILLIS = 2_000;

    @FuzzTest(maxDuration = "5m")
    void sceneRenders(byte[] data) throws InterruptedException {
        String json = new String(data, StandardCharsets.UTF_8);
        SceneDocument document;
        try {
            document = SceneLoader.parse(json, "fuzz.json");
            RenderDocument render = document.render() == null
                    ? null
                    : document.render().withSize(4, 3).withThreads(1);
            document = render == null ? document : document.withRender(render);
            LoadedScene loaded = SceneLoader.build(document, "fuzz.json", OBJ_FOLDER, json);
            renderWithin(loaded.camera());
        } catch (SceneFileException expected) {
            // the declared error
        }
    }

    /** Renders on a thread of its own; past the limit the render is cancelled, which must end it promptly. */
    private static void renderWithin(Camera camera) throws InterruptedException {
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread thread = new Thread(() -> {
            try {
                camera.renderImage();
            } catch (CancellationException cancelled) {
                // over the limit: fine
            } catch (Throwable e) {
                failure.set(e);
            }
        });
        thread.start();
        thread.join(RENDER_LIMIT_MILLIS);
        if (thread.isAlive()) {
            camera.cancel();
            thread.join(10_000);
            if (thread.isAlive()) throw new AssertionError("the render did not stop within 10 s of cancel()");
        }
        if (failure.get() != null) throw new AssertionError("the render failed: " + failure.get(), failure.get());
    }
}
