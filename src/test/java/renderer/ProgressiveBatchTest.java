package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import sceneio.LoadedScene;
import sceneio.SceneLoader;

/**
 * A batch of progressive samples (one shading of the reused first hit with every sample's shadow rays) against the
 * same samples taken one by one: the same shadow rays, and the sum of the colours up to rounding.
 */
class ProgressiveBatchTest {
    private static Camera povScene(String extra) throws Exception {
        String json = Files.readString(Path.of("scenes/povray/soft-shadow.json"))
                .replace("\"width\": 256", "\"width\": 32")
                .replace("\"height\": 256", "\"height\": 32")
                .replace("\"threads\": 1 }", "\"threads\": 1" + extra + " }");
        LoadedScene loaded = SceneLoader.load(json, "soft-shadow.json", Path.of("scenes/povray"));
        Camera camera = loaded.camera();
        camera.renderImage(); // prepares the tracer
        return camera;
    }

    @Test
    void aBatchSumsTheSamplesItStandsFor() throws Exception {
        Camera camera = povScene("");
        PixelSampler pixels = new PixelSampler(camera);
        int penumbra = 0;
        for (int y = 0; y < 32; y += 3) {
            for (int x = 0; x < 32; x += 3) {
                for (int half = 0; half < 2; half++) {
                    TraceContext one = new TraceContext(), batch = new TraceContext();
                    pixels.progressiveSample(x, y, half, 0, false, one);
                    pixels.progressiveSample(x, y, half, 0, false, batch);
                    double r = 0, g = 0, b = 0;
                    for (int i = 1; i <= 6; i++) {
                        pixels.progressiveSample(x, y, half, i, true, one);
                        r += one.red;
                        g += one.green;
                        b += one.blue;
                    }
                    assertTrue(pixels.progressiveBatch(x, y, half, 1, 6, batch), "batched");
                    assertEquals(r, batch.red, 1e-9 * (1 + r), "red at " + x + ", " + y);
                    assertEquals(g, batch.green, 1e-9 * (1 + g), "green at " + x + ", " + y);
                    assertEquals(b, batch.blue, 1e-9 * (1 + b), "blue at " + x + ", " + y);
                    assertEquals(one.counters.shadow, batch.counters.shadow, "the same shadow rays");
                    if (Math.abs(r - 6 * one.red) > 1e-6) penumbra++;
                }
            }
        }
        assertTrue(penumbra > 0, "some batches straddle a penumbra, where samples differ");
    }

    @Test
    void adaptiveShadowsAndSingleSamplesAreNotBatched() throws Exception {
        Camera camera = povScene(", \"adaptiveShadows\": true");
        PixelSampler pixels = new PixelSampler(camera);
        TraceContext ctx = new TraceContext();
        pixels.progressiveSample(5, 5, 0, 0, false, ctx);
        assertFalse(pixels.progressiveBatch(5, 5, 0, 1, 4, ctx), "adaptive probes decide per sample");
        assertFalse(pixels.progressiveBatch(5, 5, 0, 1, 1, ctx), "one sample is no batch");
    }
}
