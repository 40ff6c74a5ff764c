package renderer;

/**
 * How fast a progressive render's pixel errors fall with their samples: a pixel's MSE as {@code n^-alpha}, with the
 * exponent fitted to the render's own passes.
 *
 * <p>Independent samples give alpha = 1. The progressive beams continue one low-discrepancy sequence per pixel half,
 * which does better: measured on the accuracy report's experiments and the POV-Ray comparison scene, the pixels a
 * plan refined ended at 0.34-0.88 of the MSE the 1/n law had promised (alpha 1.34-1.53 in the first refining pass).
 * Planning with alpha = 1 there overshoots the target with samples it did not need. The first plan, with nothing
 * measured yet, assumes {@value #PRIOR}, below every first pass measured; each later plan fits alpha to what the
 * pass before it achieved, within [{@value #MIN}, {@value #MAX}]. A wrong exponent costs samples or a pass: the render
 * stops on the measured estimates, which the law only carries from a pixel's neighbours to the pixel's own samples
 * ({@link PassPlanner}'s prediction).
 */
final class ConvergenceLaw {
    static final double PRIOR = 1.25, MIN = 1, MAX = 2;
    /** The fewest refined pixels a fit needs. */
    private static final int MIN_REFINED = 64;

    private double alpha = PRIOR;
    /** Per pixel, at the last plan: its predicted MSE then and its samples per half then. */
    private final double[] plannedMse;

    private final int[] plannedDone;
    private boolean planned;
    /** {@code n^-alpha} for n = 0 .. length - 1 (entry 0 unused), for the current alpha. */
    private double[] inversePowers = new double[0];

    private double tableAlpha = Double.NaN;

    ConvergenceLaw(int pixels) {
        plannedMse = new double[pixels];
        plannedDone = new int[pixels];
    }

    /** The exponent the next plan uses. */
    double alpha() {
        return alpha;
    }

    /**
     * Fits alpha to the pixels the last plan refined: the alpha for which their MSEs predicted then, scaled by
     * {@code (samples then / samples now)^alpha}, add up to the MSEs measured now ({@code mse}, per pixel). Pixels a
     * plan picks for their high estimates tend to show lower ones afterwards (the estimates are noisy); the fit
     * includes that, as the next plan will meet it too.
     */
    void fit(double[] mse, int[] done) {
        if (!planned) return;
        double measured = 0;
        int refined = 0;
        for (int p = 0; p < done.length; p++) {
            if (done[p] > plannedDone[p]) {
                measured += mse[p];
                refined++;
            }
        }
        // A pass that refined only a few pixels says little about the law (its last steps toward the target).
        if (refined < Math.max(MIN_REFINED, done.length / 256)) return;
        double[] logRatio = new double[refined], before = new double[refined];
        for (int p = 0, k = 0; p < done.length; p++) {
            if (done[p] > plannedDone[p]) {
                logRatio[k] = Math.log((double) plannedDone[p] / done[p]);
                before[k++] = plannedMse[p];
            }
        }
        // The predicted sum falls as alpha grows. To 1/256: the plans change little below that.
        double lo = MIN, hi = MAX;
        if (predictedSum(before, logRatio, MIN) <= measured) {
            alpha = MIN;
            return;
        }
        if (predictedSum(before, logRatio, MAX) >= measured) {
            alpha = MAX;
            return;
        }
        while (hi - lo > 1.0 / 256) {
            double mid = (lo + hi) / 2;
            if (predictedSum(before, logRatio, mid) > measured) lo = mid;
            else hi = mid;
        }
        alpha = (lo + hi) / 2;
    }

    private static double predictedSum(double[] before, double[] logRatio, double alpha) {
        double sum = 0;
        for (int k = 0; k < before.length; k++) sum += before[k] * Math.exp(alpha * logRatio[k]);
        return sum;
    }

    /** Records the plan about to run: each pixel's MSE now and its samples per half now. */
    void remember(double[] mse, int[] done) {
        System.arraycopy(mse, 0, plannedMse, 0, mse.length);
        System.arraycopy(done, 0, plannedDone, 0, done.length);
        planned = true;
    }

    /** {@code n^-alpha} for every n up to {@code max}, for the current alpha (entry 0 unused). */
    double[] inversePowers(int max) {
        if (inversePowers.length <= max || tableAlpha != alpha) {
            inversePowers = new double[Math.max(max + 1, inversePowers.length)];
            for (int n = 1; n < inversePowers.length; n++) inversePowers[n] = Math.pow(n, -alpha);
            tableAlpha = alpha;
        }
        return inversePowers;
    }
}
