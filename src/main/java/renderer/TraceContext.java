package renderer;

import geometries.HitRecord;
import geometries.ShadowPacket;
import primitives.Color;
import primitives.ReusableRay;
import renderer.sampling.SampleStream;

/**
 * Everything one render thread mutates while tracing: rays, hit records, shaded points, the random stream,
 * sample buffers and the ray counters. Created once per thread and reused for every ray, so tracing allocates
 * nothing per ray: the tracer hands colours back through {@link #red}, {@link #green} and {@link #blue} instead of
 * returning objects.
 */
public final class TraceContext {
    /** Record of closest-hit queries. */
    public final HitRecord hit = new HitRecord();
    /** Record of shadow queries (kept apart so shading data survives them). */
    public final HitRecord shadowHit = new HitRecord();
    /** The camera's rays. Nothing else sets it, so a progressive sample of the same pixel centre can reuse it. */
    public final ReusableRay cameraRay = new ReusableRay();
    /** The ray of the other closest-hit queries: reflection and refraction rays, set anew for each. */
    public final ReusableRay ray = new ReusableRay();
    /** The ray of shadow queries. */
    public final ReusableRay shadowRay = new ReusableRay();
    /** Pixels this thread advances before it reads the clock again ({@link BudgetDeadline}). */
    int deadlineCountdown;

    /** The shadow rays of one disk light's beam, where they are tested together. */
    final ShadowPacket shadowPacket = new ShadowPacket();
    /** Random numbers, re-seeded per pixel, light and bounce. */
    public final SampleStream random = new SampleStream();
    /** Counts of the rays this thread fired. */
    public final RayCounters counters = new RayCounters();

    /** The colour the last trace produced (the tracer's return value). */
    public double red, green, blue;

    /** A diffuse map's value at the point being shaded (red, green, blue): the texture lookup's output. */
    final double[] texel = new double[3];

    /** The transmittance toward the light being shaded (the visibility sampler's return value). */
    double visibleR, visibleG, visibleB;
    /** Whether the last disk of shadow rays all had the same transmittance (set by the soft-shadow sampler). */
    boolean diskUniform;
    /** Direct light, in display steps, the current camera sample may still leave out (the light cut-off). */
    double cutoffBudget;

    /** Averages of the beams over a pixel and over the lens (each kind nests inside the one before). */
    final ColorAverage pixelAverage = new ColorAverage(), lensAverage = new ColorAverage();
    /**
     * In a progressive render, the index of the current sample within its pixel half (-1 otherwise) and the seed
     * of that half: effect beams (lens, shadow, glossy) then continue one Halton sequence per pixel half, sample
     * after sample, instead of drawing each beam afresh.
     */
    int sequenceIndex = -1;

    long sequenceSeed;
    /**
     * How many consecutive samples of the sequence the current shading stands for (see
     * {@link RayTracerBase#traceAgainBatch}): its shadow beams take that many samples' points at once. 1 otherwise.
     */
    int sequenceBatch = 1;
    /**
     * Whether a progressive render's points over the pixel's area, and its effect beams' points, come from
     * {@link renderer.sampling.Sobol2D} instead of Halton (a time budget's; see {@link ProgressiveSampler}).
     */
    boolean sobolArea, sobolBeams;

    /** The pixel whose progressive seeds follow (-1: none yet): its seed, and each half's seed and shift (x, y). */
    int progressivePixel = -1;

    long progressivePixelSeed;
    final long[] halfSeeds = new long[2];
    final double[] halfShifts = new double[4];

    /** Whether the last primary ray traced missed everything (for {@link RayTracerBase#traceAgain}). */
    boolean firstRayMissed;

    /**
     * The direct light at the first hit of the last primary ray, kept for the samples that shade that hit again where
     * it is the same for every sample (see SimpleRayTracer): whether it is kept, its colour, and the light cut-off's
     * budget it left.
     */
    boolean directKept;

    double directR, directG, directB, directCutoffLeft;

    /**
     * Whether the lights' unshadowed terms in {@link #direct} are those of the first hit of the last primary ray, kept
     * for the samples that shade that hit again with soft lights (see DirectLightEstimator), and the light cut-off's
     * budget they left.
     */
    boolean termsKept;

    double termsCutoffLeft;

    /**
     * {@link #continueSequence(long, int, renderer.sampling.TargetShape, double[])} for the stream of {@code stream}
     * and {@code part} (a light's index, a level), mixed only in a progressive render: other renders pay one
     * comparison.
     */
    boolean continueSequence(long stream, long part, int count, renderer.sampling.TargetShape shape, double[] out) {
        return sequenceIndex >= 0 && continueSequence(SampleStream.mix(stream, part), count, 1, shape, out);
    }

    /**
     * As {@link #continueSequence(long, long, int, renderer.sampling.TargetShape, double[])} for the current
     * {@link #sequenceBatch} of samples: {@code count} points for each, {@code count * sequenceBatch} in all, the same
     * points those samples would take one by one.
     */
    boolean continueSequenceBatch(
            long stream, long part, int count, renderer.sampling.TargetShape shape, double[] out) {
        return sequenceIndex >= 0 && continueSequence(SampleStream.mix(stream, part), count, sequenceBatch, shape, out);
    }

    /**
     * Fills {@code out} with beam {@code count} of the current sample's sequence for {@code stream} (a shifted
     * Halton continuation), or returns false outside a progressive render.
     */
    boolean continueSequence(long stream, int count, renderer.sampling.TargetShape shape, double[] out) {
        return sequenceIndex >= 0 && continueSequence(stream, count, 1, shape, out);
    }

    private boolean continueSequence(
            long stream, int count, int samples, renderer.sampling.TargetShape shape, double[] out) {
        SampleStream shift = random.reset(SampleStream.mix(sequenceSeed, stream));
        double rx = shift.nextDouble(), ry = shift.nextDouble();
        if (sobolBeams) {
            renderer.sampling.SuperSamplingBlackboard.sobolContinued(
                    count * samples, (long) sequenceIndex * count, shape, rx, ry, out);
        } else {
            renderer.sampling.SuperSamplingBlackboard.haltonContinued(
                    count * samples, (long) sequenceIndex * count, shape, rx, ry, out);
        }
        return true;
    }

    /** Adaptive anti-aliasing's lattice of one pixel: sampled colours, which points are sampled, averages. */
    static final class Lattice {
        double[] r = new double[81], g = new double[81], b = new double[81];
        boolean[] filled = new boolean[81];
        /** One average per depth of the quadrant recursion (the lattice has at most 2^10 + 1 points a side). */
        private final ColorAverage[] averages = new ColorAverage[12];

        ColorAverage average(int level) {
            ColorAverage a = averages[level];
            if (a == null) a = averages[level] = new ColorAverage();
            return a;
        }
    }

    private final Lattice lattice = new Lattice();

    /** The thread's lattice, with room for {@code points} points and none of them sampled yet. */
    Lattice lattice(int points) {
        if (lattice.filled.length < points) {
            lattice.r = new double[points];
            lattice.g = new double[points];
            lattice.b = new double[points];
            lattice.filled = new boolean[points];
        } else {
            java.util.Arrays.fill(lattice.filled, 0, points, false);
        }
        return lattice;
    }

    /** The direct light at the point being shaded (sized for the scene's lights on first use). */
    private DirectLighting direct = new DirectLighting(0);
    /** One shaded point per recursion level (the levels active at once are distinct, see SimpleRayTracer). */
    private SurfacePoint[] surfaces = new SurfacePoint[0];

    /** Sample buffers, one per kind of beam: beams of different kinds nest, beams of one kind never do. */
    private double[] pixelOffsets = new double[2 * 81];

    private double[] lensOffsets = new double[2 * 16];
    private double[] shadowOffsets = new double[2 * 81];
    private double[] glossyOffsets = new double[2 * 16];
    /** The single offset of a rough bounce below the first (read before the bounce recurses). */
    final double[] roughOffset = new double[2];
    /** A direction handed back by a helper (refraction), copied by the caller at once. */
    final double[] direction = new double[3];

    /**
     * The last traced colour as a {@link Color} (allocates; the render loop reads the fields).
     *
     * @return a new colour of the fields {@code red}, {@code green}, {@code blue}
     */
    public Color color() {
        return new Color(red, green, blue);
    }

    void setColor(double r, double g, double b) {
        red = r;
        green = g;
        blue = b;
    }

    /** The reusable shaded point of recursion level {@code level}. */
    SurfacePoint surface(int level) {
        if (level >= surfaces.length) {
            SurfacePoint[] grown = java.util.Arrays.copyOf(surfaces, Math.max(level + 1, 2 * surfaces.length));
            for (int i = surfaces.length; i < grown.length; i++) grown[i] = new SurfacePoint();
            surfaces = grown;
        }
        return surfaces[level];
    }

    /** The direct-light scratch for {@code lights} lights (made anew when the number of lights changes). */
    DirectLighting direct(int lights) {
        if (direct.lights() != lights) direct = new DirectLighting(lights);
        return direct;
    }

    /**
     * Buffer for {@code count} offsets of anti-aliasing samples over a pixel.
     *
     * @param count the number of samples
     * @return a buffer of at least {@code 2 * count} doubles, reused by later calls
     */
    public double[] pixelOffsets(int count) {
        if (pixelOffsets.length < 2 * count) pixelOffsets = new double[2 * count];
        return pixelOffsets;
    }

    /**
     * Buffer for {@code count} offsets of depth-of-field samples over the lens.
     *
     * @param count the number of samples
     * @return a buffer of at least {@code 2 * count} doubles, reused by later calls
     */
    public double[] lensOffsets(int count) {
        if (lensOffsets.length < 2 * count) lensOffsets = new double[2 * count];
        return lensOffsets;
    }

    /**
     * Buffer for {@code count} offsets of shadow rays over a light's disk.
     *
     * @param count the number of shadow rays
     * @return a buffer of at least {@code 2 * count} doubles, reused by later calls
     */
    public double[] shadowOffsets(int count) {
        if (shadowOffsets.length < 2 * count) shadowOffsets = new double[2 * count];
        return shadowOffsets;
    }

    /**
     * Buffer for {@code count} offsets of a glossy or frosted beam (only the first rough bounce splits).
     *
     * @param count the number of rays of the beam
     * @return a buffer of at least {@code 2 * count} doubles, reused by later calls
     */
    public double[] glossyOffsets(int count) {
        if (glossyOffsets.length < 2 * count) glossyOffsets = new double[2 * count];
        return glossyOffsets;
    }

    /**
     * BVH nodes visited and primitives tested, over both records.
     *
     * @return the number of nodes visited by both records
     */
    public long nodeVisits() {
        return hit.nodeVisits + shadowHit.nodeVisits;
    }

    /**
     * Primitives tested, over both records.
     *
     * @return the number of primitive tests by both records
     */
    public long primitiveTests() {
        return hit.primitiveTests + shadowHit.primitiveTests;
    }
}
