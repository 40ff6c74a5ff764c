package renderer;

import java.util.Arrays;

/**
 * The state of a progressive render (see {@link ProgressiveSettings}): per pixel, the sums of its two independent
 * halves of samples and how many each half holds, and between passes the plan of how many each pixel gets next.
 *
 * <p>A pixel's error estimate is {@code ((A - B) / 2)^2} per channel, A and B the means of its halves clamped to the
 * displayable 0..255: the expected squared error of their mean, exact for independent halves, whatever the sampling
 * pattern. Per pixel it is noisy (one degree of freedom), so the prediction averages each pixel's per-sample variance
 * over its 3 x 3 neighbourhood. The {@link PassPlanner} turns the variances into the next pass's goals, and the next
 * pass measures again.
 *
 * <p>A time budget weighs each pixel by its neighbours' estimates only, so that its own estimate, which no plan reads
 * for its own samples, predicts its error with little bias; and it draws its points from the Sobol sequence ({@link
 * renderer.sampling.Sobol2D}) rather than Halton, whose (0, 2)-nets win back more than the pixel's own estimate was
 * worth to the weights (docs/ACCURACY.md, "An honest time budget", 27 Nov). A target stops on its estimates and keeps
 * the Halton halves, with which its predictions hold within 10%.
 *
 * <p>Pixels are planned in image order and each pass's decisions depend only on the pixels' values, so the samples,
 * and the image, are the same for any number of threads (a time budget, which measures time, is the exception).
 */
final class ProgressiveSampler {
    /**
     * Samples over a pixel's area that a time budget brings every pixel to before it follows the estimates; a target
     * starts from 16. A target stops on its estimates, which 16 samples make trustworthy near edges; a budget stops on
     * time, and the floor only guards its allocation (8 did best of 4 to 16: docs/ACCURACY.md, 27 Nov).
     */
    static final int BUDGET_AREA_MINIMUM = 8;

    /**
     * Samples per half from which a time budget's passes over a pixel's area end on whole Sobol nets (through the
     * centre, from the start): below, the budget's allocation needs the finer steps ({@link PassPlanner#inWholeNets}).
     */
    static final int AREA_WHOLE_NETS_FROM = 16;

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
    /** Samples every pixel reaches first. */
    private final int minimum;
    /**
     * Whether a time budget's points over the area, or its beams' points, follow the Sobol sequence (see the class
     * description): its beams only where the pixel's area is not sampled too. With the same sequence in both, the
     * beam's first coordinate would follow the area's (point 2k's is point k's halved): on the street, 1.060 of the
     * error before instead of 0.968.
     */
    private final boolean sobolArea, sobolBeams;
    /** The plans of the passes, and the prediction they follow. */
    final PassPlanner planner;
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
        boolean timeBudget = settings.timeBudgetSeconds() > 0;
        sobolArea = timeBudget && pixels.samplesArea();
        sobolBeams = timeBudget && !pixels.samplesArea();
        planner = new PassPlanner(done, goal, variance, minimum, settings.maxSamples(), nX, nY, timeBudget);
        // A budget's points follow the Sobol sequence (see advance): whole nets of them per pass, over the area once a
        // pixel holds 16 per half.
        if (timeBudget) planner.inWholeNets(pixels.samplesArea() ? AREA_WHOLE_NETS_FROM : 0);
        // A budget starts small (4 samples) so that a short budget is kept, and not below 4 even where the minimum is
        // lower: it spends its time by the estimates, which one sample per half makes too rough (the accuracy
        // report's soft shadows at the time of 64 fixed samples, two runs four minutes apart: RMSE 4.6 starting from
        // 2, 4.0 from 4). A target starts from the minimum.
        Arrays.fill(goal, timeBudget ? FIRST_BUDGET_PASS / 2 : minimum / 2);
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
                planned = planner.planForSamples((long) (share * left / perSample));
            } else {
                planned = planner.planForError(settings.targetError());
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
     * Bytes per pixel of this state and its planner's: the halves' sums (6 doubles), the counts and goals (2 ints), the
     * variances and the planning's two arrays (3 doubles) and the law's record (a double and an int).
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
        ctx.sobolArea = sobolArea;
        ctx.sobolBeams = sobolBeams;
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
        return planner.samples();
    }

    /** The predicted RMSE of the image against the converged one ({@link PassPlanner#predictedError}). */
    double predictedError() {
        return planner.predictedError();
    }

    /** Samples per pixel: the smallest, the median and the largest. */
    private int[] sampleRange() {
        int[] sorted = done.clone();
        Arrays.sort(sorted);
        return new int[] {2 * sorted[0], 2 * sorted[sorted.length / 2], 2 * sorted[sorted.length - 1]};
    }
}
