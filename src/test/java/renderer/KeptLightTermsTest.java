package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import sceneio.LoadedScene;
import sceneio.SceneLoader;

/**
 * Progressive samples that shade a pixel's first hit again keep the lights' unshadowed terms and the light cut-off's
 * choice of the first shading (DirectLightEstimator): a sample taken that way must have the colour of the same sample
 * traced from scratch, bit for bit, with soft lights, a faint one the cut-off sets aside, a glossy floor, and one
 * context carried from pixel to pixel (the terms of one hit must never serve another).
 */
class KeptLightTermsTest {
    @Test
    void aSampleShadedAgainHasTheColourOfTheSameSampleTracedAnew() throws Exception {
        String json = Files.readString(Path.of("scenes/povray/soft-shadow.json"))
                .replace("\"width\": 256", "\"width\": 24")
                .replace("\"height\": 256", "\"height\": 24")
                .replace(
                        "\"radius\": 0.25, \"samples\": 2 }",
                        "\"radius\": 0.25, \"samples\": 2 },\n"
                                + "    { \"type\": \"point\", \"color\": [2, 2, 2], \"position\": [-2, 1, 2],"
                                + " \"radius\": 0.3, \"samples\": 4 },\n"
                                + "    { \"type\": \"point\", \"color\": [120, 100, 80], \"position\": [-1, -2, 2.5],"
                                + " \"radius\": 0.5, \"samples\": 3 }")
                // A glossy floor: its reflection rays meet the sphere (whose shading takes the terms' scratch) or
                // the sky (which leaves them kept, and the cut-off's budget as the first shading left it).
                .replace(
                        "\"kD\": [0.56, 0.56, 0.56] }",
                        "\"kD\": [0.56, 0.56, 0.56], \"kR\": 0.3, \"roughness\": 0.2 }");
        LoadedScene loaded = SceneLoader.load(json, "soft-shadow.json", Path.of("scenes/povray"));
        Camera camera = loaded.camera();
        camera.renderImage(); // prepares the tracer
        PixelSampler pixels = new PixelSampler(camera);
        TraceContext kept = new TraceContext();
        int lit = 0;
        for (int y = 0; y < 24; y += 2) {
            for (int x = 0; x < 24; x += 2) {
                for (int half = 0; half < 2; half++) {
                    pixels.progressiveSample(x, y, half, 0, false, kept);
                    for (int i = 1; i <= 3; i++) {
                        pixels.progressiveSample(x, y, half, i, true, kept);
                        TraceContext fresh = new TraceContext();
                        pixels.progressiveSample(x, y, half, i, false, fresh);
                        String where = "(" + x + ", " + y + "), half " + half + ", sample " + i;
                        assertEquals(Double.doubleToLongBits(fresh.red), Double.doubleToLongBits(kept.red), where);
                        assertEquals(Double.doubleToLongBits(fresh.green), Double.doubleToLongBits(kept.green), where);
                        assertEquals(Double.doubleToLongBits(fresh.blue), Double.doubleToLongBits(kept.blue), where);
                        if (kept.red > 0) lit++;
                    }
                }
            }
        }
        assertTrue(lit > 0, "some samples are lit");
        assertTrue(kept.counters.lightsCutOff > 0, "the faint light is set aside somewhere");
    }
}
