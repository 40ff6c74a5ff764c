package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * A target's plan where no pixel may take more samples (each at its maximum) and the target is not met: it plans
 * nothing, and finds that out in a few sums over the image. The search for the plan's factor used to halve its upper
 * bound until it reached zero, about a thousand sums, because every factor met the goal.
 */
class TargetPlanTest {
    private static final int NX = 8, NY = 6;

    @Test
    void aPlanWithEveryPixelAtItsMaximumPlansNothingInAFewSums() {
        // Samples over the pixels' areas of a floor lit at a slant: the light falls off across each pixel, so its
        // halves disagree a little.
        Camera camera = FeatureScenes.areaSampledShadowCamera(null, NX, NY);
        ProgressiveSettings settings = ProgressiveSettings.targetError(1e-6).withSamples(16, 16);
        ProgressiveSampler sampler = new ProgressiveSampler(new PixelSampler(camera), settings, NX, NY);
        TraceContext ctx = new TraceContext();
        for (int y = 0; y < NY; y++) for (int x = 0; x < NX; x++) sampler.advance(x, y, ctx);
        assertEquals(16L * NX * NY, sampler.samples(), "the first pass takes every pixel to the minimum, 16");
        assertTrue(sampler.predictedError() > 1e-6, "the target is not met: " + sampler.predictedError());

        assertEquals(0, sampler.planner.planForError(1e-6), "every pixel is at its maximum: nothing to plan");
        long steps = sampler.planner.searchSteps;
        assertTrue(steps <= 4, "the plan's search tried " + steps + " factors");
    }
}
