package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import primitives.Material;
import sceneio.SceneLoader;

/**
 * A time budget's points follow the Sobol sequence, whose first 2^m per half make a net: through the pixel's centre its
 * passes end every pixel's halves at a power of two samples; over the pixel's area, once a pixel holds 16 per half.
 */
class WholeNetsTest {
    private static final int N = 24;

    /** What a budget's passes did to the counts per half. */
    private record Counts(boolean wholeFromTheStart, boolean wholeFrom16, boolean freeBelow16) {}

    /** Runs a budget's first pass and five planned ones by hand, each of {@code perPixel} samples per pixel. */
    private static Counts passes(Camera camera, long perPixel) {
        ProgressiveSampler sampler =
                new ProgressiveSampler(new PixelSampler(camera), ProgressiveSettings.timeBudget(10), N, N);
        TraceContext ctx = new TraceContext();
        boolean whole = true, wholeFrom16 = true, freeBelow16 = false;
        int[] before = new int[N * N];
        for (int pass = 0; pass < 6; pass++) {
            if (pass > 0) assertTrue(sampler.planner.planForSamples(perPixel * N * N) > 0, "pass " + pass);
            for (int y = 0; y < N; y++) for (int x = 0; x < N; x++) sampler.advance(x, y, ctx);
            for (int p = 0; p < N * N; p++) {
                int half = sampler.samplesAt(p % N, p / N) / 2;
                boolean powerOfTwo = Integer.bitCount(half) == 1;
                whole &= powerOfTwo;
                if (half > before[p] && before[p] >= ProgressiveSampler.AREA_WHOLE_NETS_FROM) wholeFrom16 &= powerOfTwo;
                if (half < ProgressiveSampler.AREA_WHOLE_NETS_FROM && !powerOfTwo) freeBelow16 = true;
                before[p] = half;
            }
        }
        return new Counts(whole, wholeFrom16, freeBelow16);
    }

    @Test
    void throughTheCentreEveryPassEndsOnAPowerOfTwoPerHalf() throws Exception {
        String json = Files.readString(Path.of("scenes/povray/soft-shadow.json"))
                .replace("\"width\": 256", "\"width\": " + N)
                .replace("\"height\": 256", "\"height\": " + N);
        Camera camera = SceneLoader.load(json, "soft-shadow.json", Path.of("scenes/povray"))
                .camera();
        camera.renderImage(); // prepares the tracer
        assertTrue(passes(camera, 8).wholeFromTheStart());
    }

    @Test
    void overThePixelsAreaTheCountsAreFreeBelow16PerHalfAndWholeNetsFromThere() {
        Counts counts = passes(FeatureScenes.areaSampledShadowCamera(new Material().setKd(0.5), N, N), 24);
        assertTrue(counts.freeBelow16(), "some pixel below 16 per half ends between two powers of two");
        assertTrue(counts.wholeFrom16(), "a pixel that held 16 per half or more ends each pass on a power of two");
    }
}
