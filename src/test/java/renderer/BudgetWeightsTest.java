package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A time budget weighs each pixel by its neighbours' estimates, not its own: a pixel whose own estimate jumps a
 * hundredfold takes no more samples, and its neighbours take more. So no plan reads a pixel's own estimate to choose
 * its samples, and the estimate predicts its error with little bias. (Weighed by its own estimate too, until 27 Nov,
 * it took more.)
 */
class BudgetWeightsTest {
    private static final int N = 12;

    @Test
    void aPixelsOwnEstimateDoesNotRaiseItsOwnSamples() {
        SplittableRandom random = new SplittableRandom(5);
        double[] variance = new double[N * N];
        for (int p = 0; p < variance.length; p++) variance[p] = 1 + random.nextDouble();
        int centre = (N / 2) * N + N / 2;
        int[] before = plan(variance);
        variance[centre] *= 100;
        int[] after = plan(variance);

        assertTrue(
                after[centre] <= before[centre],
                "its own estimate raised its goal from " + before[centre] + " to " + after[centre]);
        assertTrue(after[centre + 1] > before[centre + 1], "its neighbour's goal: " + before[centre + 1]);
    }

    /** The goals of a budget's plan of 16 more samples per pixel, every pixel at 4 per half (the minimum of 8). */
    private static int[] plan(double[] variance) {
        int[] done = new int[N * N], goal = new int[N * N];
        Arrays.fill(done, 4);
        new PassPlanner(done, goal, variance.clone(), 8, 4096, N, N, true).planForSamples(16L * N * N);
        return goal;
    }
}
