package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import primitives.Material;

/**
 * A time budget's plan weighs each pixel by its own estimate or its neighbourhood's mean, not by its neighbourhood's
 * largest: beside a hard shadow's edge, a flat pixel takes fewer samples than the edge pixel with the image's largest
 * estimate. (Weighed by the neighbourhood's largest, every neighbour of that pixel weighed as much as it, and took as
 * many.)
 */
class BudgetWeightsTest {
    private static final int N = 24;

    @Test
    void aFlatPixelBesideTheMostSampledEdgePixelTakesFewerSamples() {
        Camera camera = FeatureScenes.areaSampledShadowCamera(new Material(), N, N);
        ProgressiveSampler sampler =
                new ProgressiveSampler(new PixelSampler(camera), ProgressiveSettings.timeBudget(10), N, N);
        TraceContext ctx = new TraceContext();
        Runnable pass = () -> {
            for (int y = 0; y < N; y++) for (int x = 0; x < N; x++) sampler.advance(x, y, ctx);
        };
        pass.run();
        sampler.planner.planForSamples(Long.MAX_VALUE / 4); // to the minimum, 8 per pixel
        pass.run();
        int mostX = 1, mostY = 1;
        for (int y = 1; y < N - 1; y++) {
            for (int x = 1; x < N - 1; x++) {
                if (sampler.varianceAt(x, y) > sampler.varianceAt(mostX, mostY)) {
                    mostX = x;
                    mostY = y;
                }
            }
        }
        sampler.planner.planForSamples(8L * N * N); // half as many again, where the estimates are
        pass.run();

        int most = sampler.samplesAt(mostX, mostY), fewest = Integer.MAX_VALUE;
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) fewest = Math.min(fewest, sampler.samplesAt(mostX + dx, mostY + dy));
        }
        assertTrue(most > 16, "the budget refined some pixel: " + most);
        assertTrue(
                fewest < most,
                "pixel (" + mostX + ", " + mostY + ") took " + most + " samples and each of its neighbours as many");
    }
}
