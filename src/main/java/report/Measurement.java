package report;

import java.util.Locale;

/**
 * One measured render of an experiment: what was spent (samples, wall time, rays by kind) and what it bought
 * (error against the converged reference).
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

    public long rays() {
        return cameraRays + shadowRays + secondaryRays;
    }

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
