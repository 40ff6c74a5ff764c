package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * The planner's predicted error where a pass refined some pixels and not their neighbours: each neighbour's estimate
 * is carried to the pixel's own samples by the convergence law. On an image whose every pixel follows the law exactly,
 * the prediction is then exactly the pixels' own errors; carried as 1/n, the neighbours' larger sample counts promised
 * the pixels beside them too little error.
 */
class PredictedErrorTest {
    private static final int NX = 5, NY = 5;

    @Test
    void aNeighboursEstimateIsCarriedToThePixelsSamplesByTheLaw() {
        int n = NX * NY;
        int[] done = new int[n];
        int[] goal = new int[n];
        double[] variance = new double[n];
        double alpha = ConvergenceLaw.PRIOR; // no pass fitted yet
        double c = 3.0; // every pixel's MSE is c * done^-alpha
        double expectedMse = 0;
        for (int p = 0; p < n; p++) {
            // A refined band (64 samples per half) down the middle column, 4 per half elsewhere.
            done[p] = p % NX == NX / 2 ? 64 : 4;
            double mse = c * Math.pow(done[p], -alpha);
            variance[p] = mse * 2.0 * done[p]; // the variance of one sample, as the sampler stores it
            expectedMse += mse / n;
        }
        PassPlanner planner = new PassPlanner(done, goal, variance, 8, 4096, NX, NY, false);

        double predicted = planner.predictedError();

        assertEquals(Math.sqrt(expectedMse), predicted, 1e-12 * Math.sqrt(expectedMse));
        // The rule until 27 Nov misses it: it promised the pixels beside the band the error of the band's samples.
        double asIndependentSamples =
                Math.sqrt(Arrays.stream(oneOverNPrediction(done, variance)).sum() / n);
        assertTrue(
                asIndependentSamples < 0.97 * predicted,
                "carried as 1/n: " + asIndependentSamples + " against " + predicted);
    }

    /**
     * A time budget predicts from each pixel's own estimate, which its plans do not read (they weigh a pixel by its
     * neighbours'): the image's error is then the mean of the pixels' own. On the same image a target's neighbourhood
     * prediction differs, since it carries the band's estimates to the pixels beside it.
     */
    @Test
    void aTimeBudgetPredictsFromThePixelsOwnEstimates() {
        int n = NX * NY;
        int[] done = new int[n];
        double[] variance = new double[n];
        double expectedMse = 0;
        for (int p = 0; p < n; p++) {
            done[p] = p % NX == NX / 2 ? 64 : 4;
            double mse = (p % NX == NX / 2 ? 5.0 : 0.2) / done[p]; // a noisy band, flat pixels beside it
            variance[p] = mse * 2.0 * done[p];
            expectedMse += mse / n;
        }
        double budget = new PassPlanner(done, new int[n], variance, 8, 4096, NX, NY, true).predictedError();
        double target = new PassPlanner(done, new int[n], variance, 8, 4096, NX, NY, false).predictedError();

        assertEquals(Math.sqrt(expectedMse), budget, 1e-12 * budget);
        assertTrue(Math.abs(target / budget - 1) > 0.05, "a target's prediction: " + target + " against " + budget);
    }

    /** Per pixel, the neighbourhood's mean variance of one sample over the pixel's samples: the rule until 27 Nov. */
    private static double[] oneOverNPrediction(int[] done, double[] variance) {
        double[] mse = new double[done.length];
        for (int y = 0; y < NY; y++) {
            for (int x = 0; x < NX; x++) {
                double sum = 0;
                int count = 0;
                for (int j = Math.max(0, y - 1); j <= Math.min(NY - 1, y + 1); j++) {
                    for (int i = Math.max(0, x - 1); i <= Math.min(NX - 1, x + 1); i++) {
                        sum += variance[j * NX + i];
                        count++;
                    }
                }
                mse[y * NX + x] = sum / count / (2.0 * done[y * NX + x]);
            }
        }
        return mse;
    }
}
