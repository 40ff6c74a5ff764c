package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import primitives.Material;
import sceneio.SceneLoader;

/**
 * A time budget's beams through the pixel's centre follow the Sobol points, whose first 2^m per half make a net; so
 * its passes end every pixel's halves at a power of two samples, where over the pixel's area they need not.
 */
class WholeNetsTest {
    private static final int N = 24;

    /** Runs a budget's first pass and four planned ones by hand; returns whether every count stayed a power of two. */
    private static boolean everyPassEndsOnWholeNets(Camera camera) {
        ProgressiveSampler sampler =
                new ProgressiveSampler(new PixelSampler(camera), ProgressiveSettings.timeBudget(10), N, N);
        TraceContext ctx = new TraceContext();
        boolean whole = true;
        for (int pass = 0; pass < 5; pass++) {
            if (pass > 0) {
                long planned = sampler.planner.planForSamples((3L + pass) * N * N);
                assertTrue(planned > 0, "pass " + pass + " planned nothing");
            }
            for (int y = 0; y < N; y++) for (int x = 0; x < N; x++) sampler.advance(x, y, ctx);
            for (int y = 0; y < N; y++) {
                for (int x = 0; x < N; x++) whole &= Integer.bitCount(sampler.samplesAt(x, y) / 2) == 1;
            }
        }
        return whole;
    }

    @Test
    void throughTheCentreEveryPassEndsOnAPowerOfTwoPerHalf() throws Exception {
        String json = Files.readString(Path.of("scenes/povray/soft-shadow.json"))
                .replace("\"width\": 256", "\"width\": " + N)
                .replace("\"height\": 256", "\"height\": " + N);
        Camera camera = SceneLoader.load(json, "soft-shadow.json", Path.of("scenes/povray"))
                .camera();
        camera.renderImage(); // prepares the tracer
        assertTrue(everyPassEndsOnWholeNets(camera));
    }

    @Test
    void overThePixelsAreaTheCountsAreFree() {
        assertTrue(!everyPassEndsOnWholeNets(FeatureScenes.areaSampledShadowCamera(new Material().setKd(0.5), N, N)));
    }
}
