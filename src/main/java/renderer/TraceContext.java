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
    /** Whether the last disk of shadow rays all had the same transmittance (set by the soft-shadow sampler). */
    boolean diskUniform;

    /** Sample buffers, one per kind of beam: beams of different kinds nest, beams of one kind never do. */
    private double[] pixelOffsets = new double[2 * 81];

    private double[] lensOffsets = new double[2 * 16];
    private double[] shadowOffsets = new double[2 * 81];
    private double[] glossyOffsets = new double[2 * 16];

    /** Buffer for {@code count} offsets of anti-aliasing samples over a pixel. */
    public double[] pixelOffsets(int count) {
        if (pixelOffsets.length < 2 * count) pixelOffsets = new double[2 * count];
        return pixelOffsets;
    }

    /** Buffer for {@code count} offsets of depth-of-field samples over the lens. */
    public double[] lensOffsets(int count) {
        if (lensOffsets.length < 2 * count) lensOffsets = new double[2 * count];
        return lensOffsets;
    }

    /** Buffer for {@code count} offsets of shadow rays over a light's disk. */
    public double[] shadowOffsets(int count) {
        if (shadowOffsets.length < 2 * count) shadowOffsets = new double[2 * count];
        return shadowOffsets;
    }

    /** Buffer for {@code count} offsets of a glossy or frosted beam (only the first rough bounce splits). */
    public double[] glossyOffsets(int count) {
        if (glossyOffsets.length < 2 * count) glossyOffsets = new double[2 * count];
        return glossyOffsets;
    }

    /** BVH nodes visited and primitives tested, over both records. */
    public long nodeVisits() {
        return hit.nodeVisits + shadowHit.nodeVisits;
    }

    public long primitiveTests() {
        return hit.primitiveTests + shadowHit.primitiveTests;
    }
}
