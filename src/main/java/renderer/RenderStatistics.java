package renderer;

import java.util.Locale;

/**
 * What a render cost: wall time (and the part spent compiling the scene), rays fired by kind, intersection work
 * and adaptive savings, with the effect plan it followed. Returned by every render.
 *
 * @param wallSeconds total render time including preparation
 * @param preparationSeconds time compiling the scene (flattening and BVH build)
 * @param threads render threads used
 * @param pixels pixels rendered
 * @param rays rays fired by kind, summed over threads
 * @param nodeVisits BVH nodes visited by all queries
 * @param primitiveTests primitive intersection tests by all queries
 * @param plan the effect plan (simulated and skipped effects)
 */
public record RenderStatistics(
        double wallSeconds,
        double preparationSeconds,
        int threads,
        long pixels,
        RayCounters rays,
        long nodeVisits,
        long primitiveTests,
        String plan) {

    /**
     * Rays of every kind per second of wall time, in millions.
     *
     * @return millions of rays per second, preparation time excluded
     */
    public double megaRaysPerSecond() {
        return rays.total() / Math.max(wallSeconds - preparationSeconds, 1e-9) * 1e-6;
    }

    /**
     * A readable multi-line report.
     *
     * @return the report, one fact per line
     */
    public String format() {
        StringBuilder s = new StringBuilder();
        s.append(String.format(
                Locale.ROOT,
                "render: %.3f s wall (%.3f s preparing), %d thread(s), %d pixels%n",
                wallSeconds,
                preparationSeconds,
                threads,
                pixels));
        s.append(String.format(
                Locale.ROOT,
                "rays:   %,d total = %,d camera + %,d shadow + %,d reflection + %,d refraction"
                        + " (%,d glossy, %,d through the lens); %.2f M rays/s%n",
                rays.total(),
                rays.camera,
                rays.shadow,
                rays.reflection,
                rays.refraction,
                rays.glossy,
                rays.depthOfField,
                megaRaysPerSecond()));
        long queries = Math.max(1, rays.total());
        s.append(String.format(
                Locale.ROOT,
                "work:   %,d BVH nodes visited (%.1f per ray), %,d primitive tests (%.1f per ray), %,d samples saved by adaptive sampling%n",
                nodeVisits,
                nodeVisits / (double) queries,
                primitiveTests,
                primitiveTests / (double) queries,
                rays.samplesSaved));
        if (rays.lightsCutOff > 0) {
            s.append(String.format(
                    Locale.ROOT,
                    "cut-off: %,d lights too faint to matter at a shading point were not sampled (%,d shadow rays"
                            + " saved at the least)%n",
                    rays.lightsCutOff,
                    rays.shadowRaysCutOff));
        }
        if (!plan.isEmpty()) s.append(plan).append(System.lineSeparator());
        return s.toString();
    }

    @Override
    public String toString() {
        return format();
    }
}
