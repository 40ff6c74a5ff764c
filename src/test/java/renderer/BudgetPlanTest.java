package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * A time budget's plan toward the minimum samples, with samples over the pixel's area (minimum 8 by default, 16 here
 * where asked): as far as the budget goes, and by one sample per half at least even when the budget, counted in samples at the time per sample
 * measured so far, cannot pay for that. The pass then stops at the budget's end; the time per sample measured over a
 * command line's first pass is the JIT's, many times the next pass's, and the render used to end there with most of
 * its budget left.
 */
class BudgetPlanTest {
    private static final int NX = 8, NY = 6;

    /** A sampler after its first pass, with the minimum 16: every pixel holds 2 samples per half. */
    private static ProgressiveSampler afterFirstPass() {
        return afterFirstPass(
                ProgressiveSettings.timeBudget(10).withSamples(16, ProgressiveSettings.DEFAULT_MAX_SAMPLES));
    }

    private static ProgressiveSampler afterFirstPass(ProgressiveSettings settings) {
        Camera camera = FeatureScenes.areaSampledShadowCamera(null, NX, NY);
        ProgressiveSampler sampler = new ProgressiveSampler(new PixelSampler(camera), settings, NX, NY);
        TraceContext ctx = new TraceContext();
        for (int y = 0; y < NY; y++) for (int x = 0; x < NX; x++) sampler.advance(x, y, ctx);
        assertEquals(4L * NX * NY, sampler.samples(), "the first pass of a budget: 4 samples per pixel");
        return sampler;
    }

    @Test
    void aBudgetShortOfAWholeStepStillRaisesEveryPixelByOneSamplePerHalf() {
        assertEquals(2L * NX * NY, afterFirstPass().planner.planForSamples(1));
    }

    @Test
    void aBudgetThatPaysForSeveralStepsTakesThemAll() {
        // To 5 samples per half: 3 more per half, 6 per pixel, which a budget of 6 per pixel pays for, not more.
        assertEquals(6L * NX * NY, afterFirstPass().planner.planForSamples(6L * NX * NY));
        // The minimum (16, 8 per half) caps the steps however large the budget.
        assertEquals(12L * NX * NY, afterFirstPass().planner.planForSamples(1_000_000));
    }

    @Test
    void aBudgetsAutomaticMinimumOverTheAreaIs8() {
        // From 2 to 4 samples per half, 4 per pixel, however large the budget.
        assertEquals(
                4L * NX * NY,
                afterFirstPass(ProgressiveSettings.timeBudget(10)).planner.planForSamples(1_000_000));
    }

    @Test
    void aBudgetsPlanComesCloseToItsSamplesInAFewSums() {
        ProgressiveSampler sampler = afterFirstPass(ProgressiveSettings.timeBudget(10)); // minimum 8: 4 per half
        assertEquals(4L * NX * NY, sampler.planner.planForSamples(1_000_000));
        TraceContext ctx = new TraceContext();
        for (int y = 0; y < NY; y++) for (int x = 0; x < NX; x++) sampler.advance(x, y, ctx);

        long before = sampler.planner.searchSteps, budget = 40L * NX * NY;
        long planned = sampler.planner.planForSamples(budget);
        long steps = sampler.planner.searchSteps - before;
        assertTrue(planned < budget && planned > 0.95 * budget, planned + " samples planned for " + budget);
        // Halving the factor took 19 sums over the image for the same plan.
        assertTrue(steps <= 10, "the plan's search tried " + steps + " factors");
    }

    @Test
    void aBudgetBeyondEveryPixelsMaximumPlansNothingInAFewSteps() {
        // Minimum and maximum 16: after the pass to the minimum every pixel is at its maximum.
        ProgressiveSampler sampler =
                afterFirstPass(ProgressiveSettings.timeBudget(10).withSamples(16, 16));
        assertEquals(12L * NX * NY, sampler.planner.planForSamples(1_000_000));
        TraceContext ctx = new TraceContext();
        for (int y = 0; y < NY; y++) for (int x = 0; x < NX; x++) sampler.advance(x, y, ctx);

        long before = sampler.planner.searchSteps;
        assertEquals(0, sampler.planner.planForSamples(1_000_000), "every pixel is at its maximum: nothing to plan");
        // The search used to double its factor up to 10^30 first, about a hundred sums over the image.
        long steps = sampler.planner.searchSteps - before;
        assertTrue(steps <= 4, "the plan's search tried " + steps + " factors");
    }
}
