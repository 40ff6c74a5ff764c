package renderer;

import java.util.Locale;

/**
 * What a progressive render predicted and spent: the image's estimated RMSE against the converged image (display
 * steps, 0..255 scale), the samples taken, the passes, and the samples per pixel (fewest, median, most).
 *
 * @param settings the target or budget asked for
 * @param predictedError the estimated RMSE of the image
 * @param samples camera samples taken in all
 * @param passes passes over the image
 * @param minSamples the fewest samples of a pixel
 * @param medianSamples the median samples of a pixel
 * @param maxSamples the most samples of a pixel
 */
public record ProgressiveReport(
        ProgressiveSettings settings,
        double predictedError,
        long samples,
        int passes,
        int minSamples,
        int medianSamples,
        int maxSamples) {

    /**
     * One line for the render statistics.
     *
     * @return e.g. "progressive: target RMSE 2, predicted 1.93 after 3 passes; 1,234,567 samples, 8 to 512 per
     *     pixel (median 8)"
     */
    public String describe() {
        String asked = settings.targetError() > 0
                ? String.format(Locale.ROOT, "target RMSE %.3g", settings.targetError())
                : String.format(Locale.ROOT, "time budget %.3g s", settings.timeBudgetSeconds());
        return String.format(
                Locale.ROOT,
                "progressive: %s, predicted RMSE %.3f after %d passes; %,d samples, %d to %d per pixel (median %d)",
                asked,
                predictedError,
                passes,
                samples,
                minSamples,
                maxSamples,
                medianSamples);
    }
}
