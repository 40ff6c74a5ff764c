package renderer;

import java.util.Arrays;

/**
 * The state of a progressive render (see {@link ProgressiveSettings}): per pixel, the sums of its two independent
 * halves of samples and how many each half holds, and between passes the plan of how many each pixel gets next.
 *
 * <p>A pixel's error estimate is {@code ((A - B) / 2)^2} per channel, A and B the means of its halves clamped to the
 * displayable 0..255: the expected squared error of their mean, exact for independent halves, whatever the sampling
 * pattern. Per pixel it is noisy (one degree of freedom), so the prediction averages each pixel's per-sample variance
 * over its 3 x 3 neighbourhood. A target's plan weighs pixels by the neighbourhood's largest, and assumes each pixel's
 * MSE falls as {@code n^-alpha}, alpha fitted to the passes so far ({@link ConvergenceLaw}); a time budget's plan
 * weighs them by the fourth root of their own estimate or the neighbourhood's mean ({@link #budgetWeights}). The next
 * pass measures again.
 *
 * <p>Pixels are planned in image order and each pass's decisions depend only on the pixels' values, so the samples,
 * and the image, are the same for any number of threads (a time budget, which measures time, is the exception).
 */
final class ProgressiveSampler {
    /** A pass may multiply a pixel's samples by at most this: estimates are checked again before going further. */
    private static final int GROWTH = 8;
    /** The share of the target's MSE a plan aims at. */
    private static final double LANDING = 0.97;
    /**
     * Samples over a pixel's area that a time budget brings every pixel to before it follows the estimates: 8, where a
     * target starts from 16. A target stops on its estimates, which 16 samples make trustworthy near edges; a budget
     * stops on time, and the floor only guards its allocation. Measured at equal samples (budgets counted in samples,
     * geometric means): anti-aliasing 6.3% less error than with 16 at 0.5-1.3 M samples, 29% at 0.2-0.5 M, 3.4% at
     * 2.5-5 M; the street 1.6% less at 40-300 k, level at 0.4-3 M; 4, 6, 10 and 12 did worse than 8 on both. Timed
     * (the budgets at fixed HALTON's times, both builds in one JVM, renders alternated), less, since the samples it
     * moves go to edges, whose rays cost more: anti-aliasing 0.981 and 0.975 of the error at 64 samples' time, 0.951 at
     * 256's; the street 1.017 at 36's (quartiles 0.97-1.03).
     */
    static final int BUDGET_AREA_MINIMUM = 8;

    /** Samples per pixel of a time budget's first pass. */
    private static final int FIRST_BUDGET_PASS = 4;

    private final PixelSampler pixels;
    private final ProgressiveSettings settings;
    private final int nX, nY;
    /** Per pixel: red, green, blue sums of half A, then of half B. */
    private final double[] sums;
    /** Per pixel: samples in each half so far, and the count each half should reach in the coming pass. */
    private final int[] done, goal;

    private int passes;
    /**
     * Per pixel, the variance of one sample: its error estimate times its samples, set by the render thread that
     * advanced the pixel, where the samples land. (Computed by the plan, it was a whole-image loop that a command
     * line's first plan ran interpreted: 7-11 ms of a 0.25-0.35 s render of the POV-Ray scene.)
     */
    private final double[] variance;
    /** Per-pixel arrays of the planning, reused from pass to pass and filled anew by each plan. */
    private final double[] meanScratch, weightScratch;
    /** The 3 x 3 filters the planning applies to the variances. */
    private final Neighbourhoods neighbourhoods;
    /** The last predicted image MSE, and the samples taken when it was predicted (-1: none yet). */
    private double predictedMse;

    private long samplesPredicted = -1;
    /** How many times the plans so far summed the law's prediction over the image (the cost of planning). */
    long lawSums;

    /** How the pixels' errors fall with their samples, fitted pass by pass. */
    private final ConvergenceLaw law;
    /** Samples every pixel reaches first. */
    private final int minimum;
    /** A time budget's end, which stops a pass where it has come to (armed after the first pass). */
    private final BudgetDeadline deadline = new BudgetDeadline(System::nanoTime);

    ProgressiveSampler(PixelSampler pixels, ProgressiveSettings settings, int nX, int nY) {
        this.pixels = pixels;
        this.settings = settings;
        minimum = settings.minSamples() != ProgressiveSettings.AUTOMATIC
                ? settings.minSamples()
                : !pixels.samplesArea() ? 2 : settings.timeBudgetSeconds() > 0 ? BUDGET_AREA_MINIMUM : 16;
        this.nX = nX;
        this.nY = nY;
        int n = nX * nY;
        sums = new double[6 * n];
        done = new int[n];
        goal = new int[n];
        variance = new double[n];
        meanScratch = new double[n];
        weightScratch = new double[n];
        neighbourhoods = new Neighbourhoods(nX, nY);
        law = new ConvergenceLaw(n);
        // A budget starts small (4 samples) so that a short budget is kept, and not below 4 even where the minimum is
        // lower: it spends its time by the estimates, which one sample per half makes too rough (the accuracy
        // report's soft shadows at the time of 64 fixed samples, two runs four minutes apart: RMSE 4.6 starting from
        // 2, 4.0 from 4). A target starts from the minimum.
        Arrays.fill(goal, settings.timeBudgetSeconds() > 0 ? FIRST_BUDGET_PASS / 2 : minimum / 2);
    }

    /**
     * Runs the passes: the minimum samples everywhere, then passes planned from the measured errors (toward the target)
     * or from the measured time per sample (to spend the budget, which counts from {@code start}, a
     * {@link System#nanoTime()}), until the target is met, the budget spent or every pixel at its maximum.
     * {@code pass} runs {@link #advance} over every pixel on the render threads.
     */
    void render(Runnable pass, long start) {
        double budget = settings.timeBudgetSeconds();
        long passStart = System.nanoTime();
        pass.run();
        passes++;
        double perSample = (System.nanoTime() - passStart) * 1e-9 / Math.max(1, samples());
        // The first pass gives every pixel its samples whatever the time; later passes stop at the budget's end.
        if (budget > 0) deadline.arm(start + (long) (budget * 1e9));
        while (true) {
            long planned;
            if (budget > 0) {
                double left = budget - (System.nanoTime() - start) * 1e-9;
                if (left < 0.05 * budget) break;
                // Half of what is left per pass, so that a wrong guess of the time per sample (pixels differ in
                // cost) costs little; the last pass, under a fifth of the budget, takes nearly all of it.
                double share = left > 0.2 * budget ? 0.5 : 0.9;
                planned = planForSamples((long) (share * left / perSample));
            } else {
                planned = planForError(settings.targetError());
            }
            if (planned == 0) break;
            long before = samples();
            passStart = System.nanoTime();
            pass.run();
            passes++;
            long taken = samples() - before;
            if (taken > 0) perSample = (System.nanoTime() - passStart) * 1e-9 / taken;
        }
    }

    /** What the render predicted and spent. */
    ProgressiveReport report() {
        int[] range = sampleRange();
        return new ProgressiveReport(settings, predictedError(), samples(), passes, range[0], range[1], range[2]);
    }

    /**
     * Bytes per pixel of this state: the halves' sums (6 doubles), the counts and goals (2 ints), the planning's
     * arrays (3 doubles) and the law's record (a double and an int).
     */
    static final int BYTES_PER_PIXEL = 6 * 8 + 2 * 4 + 3 * 8 + 8 + 4;

    /**
     * Brings pixel (x, y) to its goal for this pass (called from the render threads, once per pixel per pass), unless a
     * time budget has run out: the pixel then keeps the samples it has.
     */
    void advance(int x, int y, TraceContext ctx) {
        int p = y * nX + x;
        int from = done[p], to = goal[p];
        if (to <= from || deadline.passed(ctx)) return;
        if (pixels.samplesArea()) {
            // Samples over the pixel's area: each traces its own camera ray, added to its half's sums as it comes.
            for (int half = 0; half < 2; half++) {
                pixels.progressiveArea(x, y, half, from, to - from, sums, 6 * p + 3 * half, ctx);
            }
        } else {
            centreSamples(p, x, y, from, to, ctx);
        }
        done[p] = Math.max(done[p], goal[p]);
        variance[p] = errorSquared(p) * 2.0 * done[p];
    }

    /**
     * Brings pixel p = (x, y) from {@code from} to {@code to} samples per half through its centre. With a pinhole
     * camera: one camera ray per pixel and pass, its first hit shaded again by every sample, and where they can by
     * all of a half's samples at once (the shadow rays of every sample).
     */
    private void centreSamples(int p, int x, int y, int from, int to, TraceContext ctx) {
        boolean located = pixels.locateCentre(x, y, ctx);
        for (int half = 0; half < 2; half++) {
            int i = from;
            // Otherwise the pixel's first sample of the pass traces its camera ray, and the others follow it.
            if (half == 0 && !located) add(p, half, x, y, i++, false, ctx);
            if (pixels.progressiveBatch(x, y, half, i, to - i, ctx)) {
                addColour(p, half, ctx);
                continue;
            }
            for (; i < to; i++) add(p, half, x, y, i, true, ctx);
        }
    }

    /** Takes sample {@code index} of half {@code half} of pixel p = (x, y) and adds it to the half's sums. */
    private void add(int p, int half, int x, int y, int index, boolean again, TraceContext ctx) {
        pixels.progressiveSample(x, y, half, index, again, ctx);
        addColour(p, half, ctx);
    }

    private void addColour(int p, int half, TraceContext ctx) {
        int o = 6 * p + 3 * half;
        sums[o] += ctx.red;
        sums[o + 1] += ctx.green;
        sums[o + 2] += ctx.blue;
    }

    /** The pixel's colour: the mean of all its samples, into {@code out} (red, green, blue). */
    void mean(int x, int y, double[] out) {
        int p = y * nX + x, o = 6 * p;
        double n = 2.0 * done[p];
        out[0] = (sums[o] + sums[o + 3]) / n;
        out[1] = (sums[o + 1] + sums[o + 4]) / n;
        out[2] = (sums[o + 2] + sums[o + 5]) / n;
    }

    /** The estimated squared error of pixel {@code p}'s colour, averaged over its channels. */
    private double errorSquared(int p) {
        int o = 6 * p;
        double inverse = 1.0 / done[p], e = 0;
        for (int c = 0; c < 3; c++) {
            double a = clamp(sums[o + c] * inverse), b = clamp(sums[o + 3 + c] * inverse);
            e += (a - b) * (a - b);
        }
        return e / 12; // ((A - B) / 2)^2, averaged over the three channels
    }

    private static double clamp(double v) {
        return v < 0 ? 0 : v > 255 ? 255 : v;
    }

    /**
     * The predicted RMSE of the image against the converged one, on the 0..255 scale: per pixel, the variance of one
     * sample averaged over its 3 x 3 neighbourhood, over the pixel's samples. (The pixel's own estimate alone is
     * biased low once it has decided the pixel's samples: pixels whose few samples agreed by chance stop early and
     * keep their estimate of zero.)
     */
    double predictedError() {
        if (samples() != samplesPredicted) {
            pixelMse(variance, neighbourhoods.largest(variance, weightScratch));
        }
        return Math.sqrt(predictedMse);
    }

    /**
     * Each pixel's predicted MSE, the neighbourhood's variance of one sample over the pixel's samples (in a reused
     * array), and their mean, the image's, into {@link #predictedMse} for the samples taken so far; {@code largest}
     * holds the neighbourhoods' largest variances.
     */
    private double[] pixelMse(double[] variance, double[] largest) {
        double[] mse = neighbourhoods.mean(variance, largest, meanScratch);
        double total = 0;
        for (int p = 0; p < mse.length; p++) {
            mse[p] /= 2.0 * done[p];
            total += mse[p];
        }
        predictedMse = total / mse.length;
        samplesPredicted = samples();
        return mse;
    }

    /** The variance of one sample of pixel (x, y), as its halves estimate it. */
    double varianceAt(int x, int y) {
        return variance[y * nX + x];
    }

    /** Samples pixel (x, y) has taken so far (both halves). */
    int samplesAt(int x, int y) {
        return 2 * done[y * nX + x];
    }

    /** Samples taken so far (both halves of every pixel). */
    long samples() {
        long total = 0;
        for (int d : done) total += 2L * d;
        return total;
    }

    /** Samples per pixel: the smallest, the median and the largest. */
    private int[] sampleRange() {
        int[] sorted = done.clone();
        Arrays.sort(sorted);
        return new int[] {2 * sorted[0], 2 * sorted[sorted.length / 2], 2 * sorted[sorted.length - 1]};
    }

    /**
     * Plans the next pass toward {@code target}: the fewest samples for which the convergence law (each pixel's MSE
     * falling as {@code n^-alpha}, see {@link ConvergenceLaw}) predicts an image RMSE of {@code target}; returns the
     * samples planned (0 when the target is met or no pixel may take more).
     */
    long planForError(double target) {
        double[] largest = neighbourhoods.largest(variance, weightScratch);
        // Also kept for the report: when the target is met, no pass follows, and this is the prediction it prints.
        double[] mse = pixelMse(variance, largest);
        law.fit(mse, done);
        if (predictedMse <= target * target) return 0;
        double[] weight = weights(largest);
        // Per noisy pixel, its MSE times done^alpha: times goal^-alpha, its MSE after the pass.
        int[] noisy = noisyPixels(mse);
        double[] powers = law.inversePowers(largestHalfGoal());
        double[] scale = new double[noisy.length];
        for (int k = 0; k < noisy.length; k++) scale[k] = mse[noisy[k]] / powers[done[noisy[k]]];
        // The predicted MSE falls as lambda grows: find the least lambda that meets the target. When one pass cannot
        // (every pixel at most GROWTH times its samples), the least lambda that comes within 2% of the best this pass
        // can do: beyond it, only pixels that look flat would take more samples, and they change little.
        double reachable = 1.02 * predictedMse(scale, noisy, powers, weight, Double.POSITIVE_INFINITY);
        // A little below the target: a plan that lands on it exactly misses it by a hair half the time, and each
        // further pass costs a plan for a handful of samples (the POV-Ray scene took up to seven passes that way).
        double goalMse = Math.max(LANDING * target * target, reachable);
        if (predictedMse(scale, noisy, powers, weight, 0) <= goalMse) {
            // The pass can do no better than now (the noisy pixels are at their maximum), so every factor meets the
            // goal, and the search below would halve its bound down to zero: a thousand sums of the law over the
            // image (19 ms of an anti-aliasing render of 160 x 120 pixels held at 16 samples), to plan nothing.
            law.remember(mse, done);
            return setGoals(weight, 0);
        }
        double lo = 0, hi = 1;
        while (predictedMse(scale, noisy, powers, weight, hi) > goalMse && hi < 1e30) hi *= 2;
        // To a thousandth: the goals are whole samples, so a finer lambda changes next to nothing.
        while (hi - lo > 1e-3 * hi) {
            double mid = (lo + hi) / 2;
            if (predictedMse(scale, noisy, powers, weight, mid) > goalMse) lo = mid;
            else hi = mid;
        }
        law.remember(mse, done);
        return setGoals(weight, hi);
    }

    /** The most samples per half any pixel may reach in the coming pass. */
    private int largestHalfGoal() {
        int most = 0;
        for (int d : done) most = Math.max(most, d);
        return (int) Math.min(settings.maxSamples() / 2, (long) GROWTH * most);
    }

    /**
     * Plans the next pass to spend about {@code budget} more samples: first bringing every pixel toward the minimum
     * (evenly, as far as the budget goes), then where the estimates are highest.
     */
    long planForSamples(long budget) {
        if (budget <= 0) return 0;
        int floor = minimum / 2;
        long toFloor = 0;
        for (int d : done) toFloor += 2L * Math.max(0, floor - d);
        if (toFloor > 0) {
            // Not every pixel has the minimum yet: raise the lowest first, as far as the budget goes, and by one
            // sample per half at least: the pass stops at the budget's end (BudgetDeadline), and the time per
            // sample measured so far may be the JIT's (a command line's first pass ran 20x slower than the next).
            int lowest = Integer.MAX_VALUE;
            for (int d : done) lowest = Math.min(lowest, d);
            int level = floor;
            while (level > lowest + 1 && cost(level) > budget) level--;
            long planned = 0;
            for (int p = 0; p < done.length; p++) {
                goal[p] = Math.max(done[p], level);
                planned += 2L * (goal[p] - done[p]);
            }
            return planned;
        }
        double[] weight = budgetWeights();
        double lo = 0, hi = 1;
        while (extra(weight, hi) < budget && hi < 1e30) hi *= 2;
        while (hi - lo > 1e-3 * hi) {
            double mid = (lo + hi) / 2;
            if (extra(weight, mid) < budget) lo = mid;
            else hi = mid;
        }
        return setGoals(weight, lo);
    }

    /**
     * A time budget's share of new samples per pixel: the fourth root of its variance of one sample, the larger of its
     * own estimate and its 3 x 3 neighbourhood's mean, plus a twentieth of the image's mean (in the array of the
     * neighbourhoods' largest variances).
     *
     * <p>Not the target's weights ({@link #weights}: the square root of the neighbourhood's largest). Measured at equal
     * samples (budgets counted in samples, so that the images are deterministic; the geometric mean over 12 to 17
     * budgets), these put 0-6.9% less error on the experiments of the accuracy report: anti-aliasing 6.9%, the street
     * 5.6%, glossy 1.9%, depth of field 1.5%, soft shadows 0.0-0.8%. Two reasons: a low-discrepancy pixel's error falls faster
     * than {@code 1/n} ({@link ConvergenceLaw}), so its best share grows more slowly than its standard deviation; and a
     * pixel's estimate is noisy, so a root damps the pixels that drew a large one by chance. The neighbourhood's
     * largest spread an edge's weight over a band three pixels wide; its mean keeps what the pixel's own estimate
     * missed. A target keeps its weights: its renders stop on the measured estimate, and these took the same samples
     * within 3% there.
     */
    private double[] budgetWeights() {
        double[] largest = neighbourhoods.largest(variance, weightScratch);
        double[] mean = neighbourhoods.mean(variance, largest, meanScratch);
        double[] weight = largest;
        double sum = 0;
        for (int p = 0; p < weight.length; p++) {
            weight[p] = Math.sqrt(Math.sqrt(Math.max(variance[p], mean[p])));
            sum += weight[p];
        }
        double floor = 0.05 * sum / weight.length;
        for (int p = 0; p < weight.length; p++) weight[p] += floor;
        return weight;
    }

    /** Samples that bring every pixel's halves to at least {@code level}. */
    private long cost(int level) {
        long sum = 0;
        for (int d : done) sum += 2L * Math.max(0, level - d);
        return sum;
    }

    /**
     * Each pixel's share of new samples: the standard deviation of one sample, from the largest variance of its 3 x 3
     * neighbourhood, plus a twentieth of the image's mean, so that no pixel is given up on for having looked flat
     * to its first samples. Computed in place, in the array of the neighbourhoods' largest variances.
     */
    private static double[] weights(double[] largest) {
        double[] weight = largest;
        double mean = 0;
        for (int p = 0; p < weight.length; p++) {
            weight[p] = Math.sqrt(weight[p]);
            mean += weight[p];
        }
        mean /= weight.length;
        for (int p = 0; p < weight.length; p++) weight[p] += 0.05 * mean;
        return weight;
    }

    /** Samples per half pixel {@code p} would reach for the allocation factor {@code lambda}. */
    private int halfGoal(double[] weight, double lambda, int p) {
        int max = Math.min(settings.maxSamples() / 2, GROWTH * done[p]);
        double wanted = weight[p] > 0 ? Math.ceil(lambda * weight[p] / 2) : 0; // (infinity times 0 is NaN)
        return (int) Math.max(done[p], Math.min(max, wanted));
    }

    /**
     * The image MSE the convergence law predicts after planning with lambda: the noisy pixels' {@code scale} times
     * {@code goal^-alpha} ({@code powers}), summed (the other pixels add exactly zero), over all pixels.
     */
    private double predictedMse(double[] scale, int[] noisy, double[] powers, double[] weight, double lambda) {
        lawSums++;
        double sum = 0;
        for (int k = 0; k < noisy.length; k++) sum += scale[k] * powers[halfGoal(weight, lambda, noisy[k])];
        return sum / done.length;
    }

    /**
     * The pixels whose predicted MSE is not zero, in order. The search for the plan's lambda sums the predicted MSE
     * some 25 times; where most of the image is converged (a soft shadow's lit ground and umbra), most terms are zero.
     */
    private static int[] noisyPixels(double[] mse) {
        int count = 0;
        for (double m : mse) if (m != 0) count++;
        int[] noisy = new int[count];
        for (int p = 0, k = 0; p < mse.length; p++) if (mse[p] != 0) noisy[k++] = p;
        return noisy;
    }

    private long extra(double[] weight, double lambda) {
        long sum = 0;
        for (int p = 0; p < done.length; p++) sum += 2L * (halfGoal(weight, lambda, p) - done[p]);
        return sum;
    }

    private long setGoals(double[] weight, double lambda) {
        long planned = 0;
        for (int p = 0; p < done.length; p++) {
            goal[p] = halfGoal(weight, lambda, p);
            planned += 2L * (goal[p] - done[p]);
        }
        return planned;
    }
}
