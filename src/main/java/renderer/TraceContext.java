package renderer;

import geometries.HitRecord;
import renderer.sampling.SampleStream;

/**
 * Everything one render thread mutates while tracing: hit records, the random stream, a sample buffer and the
 * ray counters. Created once per thread and reused for every ray, so tracing allocates no per-ray scratch.
 */
public final class TraceContext {
    /** Record of closest-hit queries. */
    public final HitRecord hit = new HitRecord();
    /** Record of shadow queries (kept apart so shading data survives them). */
    public final HitRecord shadowHit = new HitRecord();
    /** Random numbers, re-seeded per pixel, light and bounce. */
    public final SampleStream random = new SampleStream();
    /** Counts of the rays this thread fired. */
    public final RayCounters counters = new RayCounters();

    private double[] offsets = new double[2 * 81];

    /** A buffer for {@code count} sample offsets (x, y pairs), grown on demand. */
    public double[] offsets(int count) {
        if (offsets.length < 2 * count) offsets = new double[2 * count];
        return offsets;
    }

    /** A second buffer, for when one beam of samples is nested in another. */
    private double[] innerOffsets = new double[2 * 81];

    public double[] innerOffsets(int count) {
        if (innerOffsets.length < 2 * count) innerOffsets = new double[2 * count];
        return innerOffsets;
    }

    /**
     * The camera's own buffers for the pixel and lens sample offsets. The camera traces rays while it walks
     * through these, and the tracer refills {@link #offsets} and {@link #innerOffsets} below it (soft shadows,
     * glossy beams), so the camera must not share them.
     */
    private double[] pixelOffsets = new double[2 * 81];

    private double[] lensOffsets = new double[2 * 81];

    /** The camera's buffer for {@code count} pixel (anti-aliasing) sample offsets. */
    double[] pixelOffsets(int count) {
        if (pixelOffsets.length < 2 * count) pixelOffsets = new double[2 * count];
        return pixelOffsets;
    }

    /** The camera's buffer for {@code count} lens (depth of field) sample offsets. */
    double[] lensOffsets(int count) {
        if (lensOffsets.length < 2 * count) lensOffsets = new double[2 * count];
        return lensOffsets;
    }

    /** BVH nodes visited and primitives tested, over both records. */
    public long nodeVisits() {
        return hit.nodeVisits + shadowHit.nodeVisits;
    }

    public long primitiveTests() {
        return hit.primitiveTests + shadowHit.primitiveTests;
    }
}
