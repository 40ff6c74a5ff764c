package renderer;

import java.util.function.DoublePredicate;

/**
 * The plans of a {@link ProgressiveSampler}'s passes, and the prediction they follow: from each pixel's variance of one
 * sample, how many samples each pixel should reach in the coming pass ({@code goal}), toward a target error
 * ({@link #planForError}) or to spend a share of a time budget ({@link #planForSamples}), and the image's predicted
 * error. The sampler's passes take the samples and set the variances; this class only reads them.
 *
 * <p>A target's plan weighs pixels by the neighbourhood's largest variance, and assumes each pixel's MSE falls as
 * {@code n^-alpha}, alpha fitted to the passes so far ({@link ConvergenceLaw}); a time budget's plan weighs them by the
 * fourth root of their neighbours' mean estimate, without their own ({@link #budgetWeights}), and predicts from the
 * pixels' own estimates.
 */
final class PassPlanner {
    /** A pass may multiply a pixel's samples by at most this: estimates are checked again before going further. */
    private static final int GROWTH = 8;
    /** The share of the target's MSE a plan aims at. */
    private static final double LANDING = 0.97;
    /** The sampler's arrays: per pixel, samples per half so far and the goal of the coming pass, and its variance. */
    private final int[] done, goal;

    private final double[] variance;
    /** Samples every pixel reaches first, and the most any may take. */
    private final int minimum, maxSamples;

    /** Per-pixel arrays of the planning, reused from pass to pass and filled anew by each plan. */
    private final double[] meanScratch, weightScratch, lawScratch;
    /** The 3 x 3 filters the planning applies to the variances. */
    private final Neighbourhoods neighbourhoods;
    /** The last predicted image MSE, and the samples taken when it was predicted (-1: none yet). */
    private double predictedMse;

    private long samplesPredicted = -1;
    /** How many factors the plans' searches have tried so far, each a sum over the image (the cost of planning). */
    long searchSteps;

    /** How the pixels' errors fall with their samples, fitted pass by pass. */
    private final ConvergenceLaw law;

    /** Whether the plans spend a time budget: then each pixel's weight comes from its neighbours' estimates only. */
    private final boolean timeBudget;

    /**
     * From how many samples per half a pixel's passes end at a power of two, a whole net of the Sobol points
     * ({@link #inWholeNets}); by default never.
     */
    private int wholeNetsFrom = Integer.MAX_VALUE;

    /** Plans for the sampler's arrays, which it fills; {@code nX} x {@code nY} pixels, toward a target or a budget. */
    PassPlanner(
            int[] done,
            int[] goal,
            double[] variance,
            int minimum,
            int maxSamples,
            int nX,
            int nY,
            boolean timeBudget) {
        this.timeBudget = timeBudget;
        this.done = done;
        this.goal = goal;
        this.variance = variance;
        this.minimum = minimum;
        this.maxSamples = maxSamples;
        int n = nX * nY;
        meanScratch = new double[n];
        weightScratch = new double[n];
        lawScratch = new double[n];
        neighbourhoods = new Neighbourhoods(nX, nY);
        law = new ConvergenceLaw(n);
    }

    /**
     * The predicted RMSE of the image against the converged one, on the 0..255 scale: per pixel, the MSEs of its 3 x 3
     * neighbourhood, each carried to the pixel's own samples by the convergence law, averaged. (The pixel's own
     * estimate alone is biased low once it has decided the pixel's samples: pixels whose few samples agreed by chance
     * stop early and keep their estimate of zero.) A time budget's plans never weigh a pixel by its own estimate, so it
     * predicts from those alone ({@link #ownMse}).
     */
    double predictedError() {
        if (timeBudget) return Math.sqrt(ownMse());
        if (samples() != samplesPredicted) {
            pixelMse(variance, neighbourhoods.largest(variance, weightScratch));
        }
        return Math.sqrt(predictedMse);
    }

    /**
     * Each pixel's predicted MSE (in a reused array), and their mean, the image's, into {@link #predictedMse} for the
     * samples taken so far; {@code largest} holds the neighbourhoods' largest variances. A neighbour's MSE at its
     * samples n is carried to the pixel's m as the law says, times {@code (n / m)^alpha}: where a pass refined the
     * neighbours of an edge and not the pixel beside them, their estimates would otherwise promise the pixel the error
     * of their samples. (Until 27 Nov it was carried as {@code n / m}, the law of independent samples; the predictions
     * of the accuracy report's target-error renders were up to 17% below their measured errors, and are now within 10%:
     * docs/ACCURACY.md.)
     */
    private double[] pixelMse(double[] variance, double[] largest) {
        double[] inversePowers = law.inversePowers(mostDone());
        // Per pixel, its MSE times its samples to the power alpha: the same for every sample count, by the law.
        double[] scaled = lawScratch;
        for (int q = 0; q < scaled.length; q++) {
            scaled[q] = variance[q] == 0 ? 0 : variance[q] / (2.0 * done[q]) / inversePowers[done[q]];
        }
        double[] mse = neighbourhoods.mean(scaled, largest, meanScratch);
        double total = 0;
        for (int p = 0; p < mse.length; p++) {
            mse[p] *= inversePowers[done[p]];
            total += mse[p];
        }
        predictedMse = total / mse.length;
        samplesPredicted = samples();
        return mse;
    }

    /**
     * The image's MSE as the mean of the pixels' own estimates: a time budget's prediction. Its plans weigh each pixel
     * by its neighbours' estimates only, and its first passes every pixel alike, so no plan reads a pixel's own
     * estimate to choose its samples. Nearly unbiased: a pixel's samples still sway its later shares a little,
     * through the shares of its neighbours, which read them (0.82-1.03 of the error on the accuracy report's
     * anti-aliasing, 0.95-1.16 elsewhere: docs/ACCURACY.md, 27 Nov). (A target plans on the pixels' own estimates,
     * which are then biased low, and predicts from its neighbourhoods.)
     */
    private double ownMse() {
        double sum = 0;
        for (int p = 0; p < done.length; p++) sum += variance[p] / (2.0 * done[p]);
        return sum / done.length;
    }

    /** Samples taken so far (both halves of every pixel). */
    long samples() {
        long total = 0;
        for (int d : done) total += 2L * d;
        return total;
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
        double[] factors = search(lambda -> predictedMse(scale, noisy, powers, weight, lambda) <= goalMse);
        law.remember(mse, done);
        return setGoals(weight, factors[1]);
    }

    /**
     * The allocation factors on either side of the least one that {@code suffices} (which holds from some factor on),
     * to a thousandth: the goals are whole samples, so a finer factor changes next to nothing. Doubling from 1, then
     * halving the interval. The ends are tried first: where 0 suffices (no pixel that would change the plan may take
     * more) both are 0, where nothing does (every pixel at its maximum) both are infinite; the search would otherwise
     * halve its bound down to zero, a thousand sums over the image (19 ms of an anti-aliasing render of 160 x 120
     * pixels held at 16 samples), or double it to 10^30, about a hundred.
     */
    private double[] search(DoublePredicate suffices) {
        DoublePredicate counted = lambda -> {
            searchSteps++;
            return suffices.test(lambda);
        };
        if (counted.test(0)) return new double[] {0, 0};
        if (!counted.test(Double.POSITIVE_INFINITY)) {
            return new double[] {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        }
        double lo = 0, hi = 1;
        while (!counted.test(hi) && hi < 1e30) hi *= 2;
        while (hi - lo > 1e-3 * hi) {
            double mid = (lo + hi) / 2;
            if (counted.test(mid)) hi = mid;
            else lo = mid;
        }
        return new double[] {lo, hi};
    }

    /** The most samples per half any pixel may reach in the coming pass. */
    private int largestHalfGoal() {
        return (int) Math.min(maxSamples / 2, (long) GROWTH * mostDone());
    }

    /** The most samples per half any pixel has. */
    private int mostDone() {
        int most = 0;
        for (int d : done) most = Math.max(most, d);
        return most;
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
        // The most samples that do not exceed the budget.
        return setGoals(weight, budgetFactor(weight, budget));
    }

    /**
     * The largest allocation factor whose plan adds fewer than {@code budget} samples, to a thousandth (the lower end
     * of {@link #search}'s interval), by regula falsi on the samples added (the Illinois variant), from a guess that
     * ignores the pixels' floors and ceilings: the samples grow nearly in proportion to the factor, so it took 4-12
     * sums over the image on the accuracy report's budgets, where halving took about 25 (docs/ACCURACY.md, 27 Nov). A
     * step that does not halve the interval is followed by a halving, so it never takes many more than halving would.
     */
    private double budgetFactor(double[] weight, long budget) {
        if (countedExtra(weight, Double.POSITIVE_INFINITY) < budget) return Double.POSITIVE_INFINITY;
        double weights = 0, done2 = 0;
        for (int p = 0; p < weight.length; p++) {
            weights += weight[p];
            done2 += 2.0 * done[p];
        }
        double lo = 0, hi = (budget + done2) / weights;
        double below = -budget, above = countedExtra(weight, hi) - budget;
        while (above < 0) {
            lo = hi;
            below = above;
            hi *= 2;
            above = countedExtra(weight, hi) - budget;
        }
        int kept = 0; // +1: the upper end moved last, -1: the lower end
        boolean halve = false;
        // Done when the factors are a thousandth apart, as the search's are, or the plan is within a thousandth of the
        // budget in samples.
        while (hi - lo > 1e-3 * hi && -below > 1e-3 * budget) {
            double width = hi - lo;
            double x;
            if (halve) x = (lo + hi) / 2;
            else if (above <= 1e-3 * budget) x = hi * (1 - 0.999e-3); // the upper end is as good: just below it
            else x = hi - above * (hi - lo) / (above - below);
            if (!(x > lo && x < hi)) x = (lo + hi) / 2;
            double f = countedExtra(weight, x) - budget;
            if (f >= 0) {
                hi = x;
                above = f;
                if (kept == 1) below /= 2;
                kept = 1;
            } else {
                lo = x;
                below = f;
                if (kept == -1) above /= 2;
                kept = -1;
            }
            halve = !halve && hi - lo > width / 2;
        }
        return lo;
    }

    /** The samples a plan with {@code lambda} would add, counted as one of the search's sums over the image. */
    private long countedExtra(double[] weight, double lambda) {
        searchSteps++;
        long sum = 0;
        for (int p = 0; p < done.length; p++) sum += 2L * (plannedGoal(weight, lambda, p) - done[p]);
        return sum;
    }

    /**
     * A time budget's share of new samples per pixel: the fourth root of the mean variance of one sample of its
     * neighbours (the pixels of its 3 x 3 neighbourhood but itself), plus a twentieth of the image's mean (written over
     * the array of the neighbourhoods' largest variances). Not the pixel's own estimate, so that its own predicts its
     * error with little bias ({@link #predictedError}): at the price of 2-3% of a budget's error in equal time, which
     * its Sobol points win back (docs/ACCURACY.md, 27 Nov). The fourth root, not the target's square root: a
     * low-discrepancy pixel's error falls faster than {@code 1/n} ({@link ConvergenceLaw}), so its best share grows
     * more slowly than its standard deviation, and a root damps the estimates that came out large by chance.
     */
    private double[] budgetWeights() {
        double[] largest = neighbourhoods.largest(variance, weightScratch);
        double[] others = neighbourhoods.meanOfOthers(variance, largest, meanScratch);
        double[] weight = largest;
        for (int p = 0; p < weight.length; p++) weight[p] = Math.sqrt(Math.sqrt(others[p]));
        return withFloor(weight);
    }

    /** Samples that bring every pixel's halves to at least {@code level}. */
    private long cost(int level) {
        long sum = 0;
        for (int d : done) sum += 2L * Math.max(0, level - d);
        return sum;
    }

    /**
     * Each pixel's share of new samples: the standard deviation of one sample, from the largest variance of its 3 x 3
     * neighbourhood, with {@link #withFloor}. Computed in place, in the array of the neighbourhoods' largest variances.
     */
    private static double[] weights(double[] largest) {
        for (int p = 0; p < largest.length; p++) largest[p] = Math.sqrt(largest[p]);
        return withFloor(largest);
    }

    /**
     * The shares plus a twentieth of their mean, in place, so that no pixel is given up on for having looked flat to
     * its first samples.
     */
    private static double[] withFloor(double[] weight) {
        double mean = 0;
        for (double w : weight) mean += w;
        mean /= weight.length;
        for (int p = 0; p < weight.length; p++) weight[p] += 0.05 * mean;
        return weight;
    }

    /**
     * From now on, a pixel that holds at least {@code from} samples per half gets goals of a power of two (rounded
     * down; at least its samples): a time budget's points follow the Sobol sequence, whose first 2^m make a
     * (0, m, 2)-net, and a count between two powers adds points that no longer cover the square evenly. Measured in
     * equal time on the accuracy report's budgets (docs/ACCURACY.md, "Whole nets for a budget's beams"): through the
     * pixel's centre from the start ({@code from} 0), soft shadows 0.891 and 0.928 of the error, depth of field
     * 0.96-1.07 (level) and 0.920, glossy 0.984 and 0.893; over the pixel's area from 16 per half, anti-aliasing
     * 0.95-1.01 and 0.95-0.97, the street 0.94-0.97. Over the area from the start, anti-aliasing's short budget lost
     * (1.040-1.062): its first passes need the finer steps.
     *
     * @param from samples per half from which a pixel's goals are whole nets
     * @return this planner
     */
    PassPlanner inWholeNets(int from) {
        wholeNetsFrom = from;
        return this;
    }

    /** Samples per half pixel {@code p} would reach for the allocation factor {@code lambda}. */
    private int halfGoal(double[] weight, double lambda, int p) {
        int max = Math.min(maxSamples / 2, GROWTH * done[p]);
        double wanted = weight[p] > 0 ? Math.ceil(lambda * weight[p] / 2) : 0; // (infinity times 0 is NaN)
        return (int) Math.max(done[p], Math.min(max, wanted));
    }

    /**
     * The goal a plan sets pixel {@code p}: {@link #halfGoal}, down to a whole net where asked ({@link #inWholeNets}).
     * (A target's search calls {@code halfGoal} itself, once per noisy pixel and step, mostly interpreted in a command
     * line's first plans, so that costs it no test.)
     */
    private int plannedGoal(double[] weight, double lambda, int p) {
        int goal = halfGoal(weight, lambda, p);
        return goal > done[p] && done[p] >= wholeNetsFrom ? Math.max(done[p], Integer.highestOneBit(goal)) : goal;
    }

    /**
     * The image MSE the convergence law predicts after planning with lambda: the noisy pixels' {@code scale} times
     * {@code goal^-alpha} ({@code powers}), summed (the other pixels add exactly zero), over all pixels.
     */
    private double predictedMse(double[] scale, int[] noisy, double[] powers, double[] weight, double lambda) {
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

    private long setGoals(double[] weight, double lambda) {
        long planned = 0;
        for (int p = 0; p < done.length; p++) {
            goal[p] = plannedGoal(weight, lambda, p);
            planned += 2L * (goal[p] - done[p]);
        }
        return planned;
    }
}
