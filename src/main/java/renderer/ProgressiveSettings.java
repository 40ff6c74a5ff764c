package renderer;

import primitives.Limits;

/**
 * Progressive sampling: instead of a fixed count of camera rays per pixel, the renderer measures its own error and
 * spends samples where the error is highest, until the image reaches a target error or the render a time budget.
 *
 * <p>Every pixel starts with its minimum of samples from two independently shifted Halton sequences (half each)
 * over the pixel's area, or, when the camera's anti-aliasing has one sample, all through the pixel's centre (then the
 * samples refine only the effects: soft shadows, depth of field, glossy surfaces);
 * the difference of the two halves' means estimates the pixel's error honestly, whatever the sampling pattern (it is
 * the error of the mean of two independent estimates, not a variance model). Between passes the samples are
 * reallocated in proportion to each pixel's estimated noise (the largest of its 3 x 3 neighbourhood, so that edges
 * seen by a neighbour are refined too), never beyond {@code maxSamples}.
 *
 * @param targetError the image RMSE to reach, in display steps (0..255 scale), or 0 for none
 * @param timeBudgetSeconds the wall time to spend on the render, or 0 for none
 * @param minSamples samples every pixel starts with when a target error is asked: even, 2 to {@code maxSamples}, or
 *     {@link #AUTOMATIC}: 16 over the pixel's area (edges need that many to be seen), 2 through its centre (one per
 *     half: where both halves' effect samples agree exactly, in full light or full shadow, the pixel is done, and a
 *     penumbra shows as a disagreement in the pixel or in a neighbour); a time budget starts from 4 and brings every
 *     pixel to the minimum (automatically 8 over the area, since a budget stops on time, not on its estimates)
 *     before spending the rest where the estimates are highest
 * @param maxSamples the most samples a pixel may receive, up to 1,048,576
 */
public record ProgressiveSettings(double targetError, double timeBudgetSeconds, int minSamples, int maxSamples) {
    /**
     * The minimum samples chosen by the sampling: 16 over a pixel's area (8 for a time budget), 2 through its centre.
     */
    public static final int AUTOMATIC = 0;
    /** The most samples a pixel receives unless told otherwise. */
    public static final int DEFAULT_MAX_SAMPLES = 4096;

    /**
     * Checks the settings.
     *
     * @param targetError the image RMSE to reach (display steps), or 0 for none
     * @param timeBudgetSeconds the wall time to spend, or 0 for none
     * @param minSamples samples every pixel starts with (even, at least 2), or {@link #AUTOMATIC}
     * @param maxSamples the most samples a pixel may receive
     * @throws IllegalArgumentException if not exactly one of target error and time budget is positive, or the sample
     *     counts are out of range
     */
    public ProgressiveSettings {
        if (!(targetError >= 0 && targetError <= 255)) {
            throw new IllegalArgumentException(
                    "target error must be 0 to 255 display steps (0: none), but was " + targetError);
        }
        if (!(timeBudgetSeconds >= 0 && timeBudgetSeconds <= 1e7)) {
            throw new IllegalArgumentException(
                    "time budget must be 0 to 1e7 seconds (0: none), but was " + timeBudgetSeconds);
        }
        if ((targetError > 0) == (timeBudgetSeconds > 0)) {
            throw new IllegalArgumentException("give exactly one of a target error and a time budget, but they were "
                    + targetError + " and " + timeBudgetSeconds + " s");
        }
        if (minSamples != AUTOMATIC && (minSamples < 2 || minSamples % 2 != 0)) {
            throw new IllegalArgumentException("minimum samples must be even and at least 2 (two halves of 1), or 0"
                    + " (automatic), but was " + minSamples);
        }
        int least = Math.max(minSamples, 16);
        if (maxSamples < least || maxSamples > Limits.MAX_SAMPLES) {
            throw new IllegalArgumentException(
                    "maximum samples must be " + least + " to " + Limits.MAX_SAMPLES + ", but was " + maxSamples);
        }
    }

    /**
     * Sample until the image's estimated RMSE is at most {@code displaySteps}.
     *
     * @param displaySteps the target RMSE on the 0..255 scale, positive
     * @return the settings
     */
    public static ProgressiveSettings targetError(double displaySteps) {
        if (!(displaySteps > 0 && displaySteps <= 255)) {
            throw new IllegalArgumentException(
                    "target error must be in (0, 255] display steps, but was " + displaySteps);
        }
        return new ProgressiveSettings(displaySteps, 0, AUTOMATIC, DEFAULT_MAX_SAMPLES);
    }

    /**
     * Sample for {@code seconds} of wall time in all, spending samples where the estimated error is highest. The first
     * pass (4 samples per pixel) always completes, so the image is complete; every later pass stops where it has come
     * to when the time is up.
     *
     * @param seconds the wall time of the whole render, positive
     * @return the settings
     */
    public static ProgressiveSettings timeBudget(double seconds) {
        if (!(seconds > 0 && seconds <= 1e7)) {
            throw new IllegalArgumentException("time budget must be in (0, 1e7] seconds, but was " + seconds);
        }
        return new ProgressiveSettings(0, seconds, AUTOMATIC, DEFAULT_MAX_SAMPLES);
    }

    /**
     * These settings with other sample bounds.
     *
     * @param min samples every pixel starts with (even, at least 2), or {@link #AUTOMATIC}
     * @param max the most samples per pixel
     * @return the new settings
     */
    public ProgressiveSettings withSamples(int min, int max) {
        return new ProgressiveSettings(targetError, timeBudgetSeconds, min, max);
    }
}
