package report;

import java.util.Locale;

/**
 * One measured render of an experiment: what was spent (samples, wall time, rays by kind) and what it bought
 * (error against the converged reference).
 *
 * @param experiment the experiment's slug
 * @param variant the variant's label
 * @param samples the sample count of the effect
 * @param seconds the render's wall time in seconds (median of the repeats)
 * @param cameraRays camera rays traced
 * @param shadowRays shadow rays traced
 * @param secondaryRays reflection and refraction rays traced
 * @param rmse root mean square error against the reference (0..255 scale)
 * @param p99 99th percentile of the per-pixel error (0..255 scale)
 */
public record Measurement(
        String experiment,
        String variant,
        int samples,
        double seconds,
        long cameraRays,
        long shadowRays,
        long secondaryRays,
        double rmse,
        double p99) {

    /** CSV header matching {@link #csv()}. */
    public static final String CSV_HEADER =
            "experiment,variant,samples,seconds,camera_rays,shadow_rays,secondary_rays,rmse,p99";

    /**
     * All rays traced.
     *
     * @return the sum of camera, shadow and secondary rays
     */
    public long rays() {
        return cameraRays + shadowRays + secondaryRays;
    }

    /**
     * This measurement as a CSV row matching {@link #CSV_HEADER}.
     *
     * @return the row, without a line break
     */
    public String csv() {
        return String.format(
                Locale.ROOT,
                "%s,%s,%d,%.6f,%d,%d,%d,%.6f,%.6f",
                experiment,
                variant,
                samples,
                seconds,
                cameraRays,
                shadowRays,
                secondaryRays,
                rmse,
                p99);
    }
}
