package report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import renderer.Camera;
import renderer.sampling.SamplingPattern;

/** The street experiment's counts, its verdict arithmetic, and that its variants render what they say. */
class StreetExperimentTest {
    private static final Variant ADAPTIVE = new Variant(SamplingPattern.GRID, true);

    private static Measurement m(String variant, int samples, double seconds, double rmse) {
        return new Measurement("street", variant, samples, seconds, 0, 0, 0, rmse, rmse);
    }

    @Test
    void everyCountIsAPerfectSquareAndTheBaselineIsMeasured() {
        int[] counts = new StreetExperiment().counts(new int[] {1, 4, 16, 64, 256});
        for (int n : counts) {
            int root = (int) Math.round(Math.sqrt(n));
            assertEquals(n, root * root, "a full square GRID: " + n);
        }
        assertEquals(StreetExperiment.BASELINE_SAMPLES, counts[counts.length - 1]);
    }

    @Test
    void timeToReachInterpolatesOnTheLogLogCurve() {
        List<Measurement> series = List.of(m("a", 1, 1, 8), m("a", 4, 4, 2), m("a", 16, 16, 0.5));
        // Error falls as 1/time here: an RMSE of 1 is reached at time 8, halfway (in logs) from 4 to 16.
        assertEquals(8, StreetExperiment.timeToReach(series, 1), 1e-9);
        assertEquals(1, StreetExperiment.timeToReach(series, 9), 0, "already below at the first measurement");
        assertTrue(Double.isNaN(StreetExperiment.timeToReach(series, 0.1)), "never reached");
    }

    @Test
    void theVerdictStatesTheFractionOfTheBaselineTime() {
        Map<String, List<Measurement>> byVariant = new LinkedHashMap<>();
        byVariant.put(Variant.GRID.label(), List.of(m("grid", 1, 1, 10), m("grid", 81, 100, 2)));
        byVariant.put(ADAPTIVE.label(), List.of(m("adaptive grid", 1, 1, 10), m("adaptive grid", 16, 10, 1)));
        String verdict = new StreetExperiment().verdict(byVariant);
        double expected = Math.exp(Math.log(10) * Math.log(10 / 2.0) / Math.log(10)); // 5 s
        assertTrue(
                verdict.contains(String.format(java.util.Locale.ROOT, "%.2f s, 5.0%% of the time", expected)), verdict);
    }

    @Test
    void adaptiveFiresFewerCameraRaysThanFixedAndBothRender() {
        StreetExperiment street = new StreetExperiment();
        Camera fixed = street.camera(Variant.GRID, 16, 12, 8).renderImage();
        Camera adaptive = street.camera(ADAPTIVE, 16, 12, 8).renderImage();
        assertEquals(12L * 8 * 16, fixed.getLastStatistics().rays().camera);
        long adaptiveRays = adaptive.getLastStatistics().rays().camera;
        assertTrue(adaptiveRays < 12L * 8 * 16 && adaptiveRays >= 12L * 8, "adaptive camera rays: " + adaptiveRays);
        assertTrue(fixed.getLastStatistics().rays().shadow
                > adaptive.getLastStatistics().rays().shadow);
    }
}
