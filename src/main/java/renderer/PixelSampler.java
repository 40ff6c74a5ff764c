package renderer;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.sampling.SampleStream;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.Sobol2D;
import renderer.sampling.SuperSamplingBlackboard;
import renderer.sampling.TargetShape;

/**
 * A camera's pixel sampling for one render: one ray through the pixel's centre or a beam over the pixel's area
 * (anti-aliasing, fixed or adaptive by corner subdivision), and with an aperture a beam over the lens for every
 * sample (depth of field); and for a {@link ProgressiveSampler}, the samples of a pixel's two halves, one by one or,
 * through the centre of a pinhole camera, a half's samples of a pass at once. Every random number derives from the
 * scene seed and the pixel's index, so a pixel's colour does not depend on the thread or the order that renders it.
 * The {@link Camera} keeps the view's geometry, the tiles and the threads.
 */
final class PixelSampler {
    private static final long AA_STREAM = 11, LENS_STREAM = 12, ADAPTIVE_PATHS = 1L << 40;
    /** Streams of progressive sampling: the two halves' shifts, and the paths of their samples. */
    private static final long PROGRESSIVE_SHIFT = 13, PROGRESSIVE_PATHS = 1L << 41;

    private final Camera camera;
    private final RayTracerBase rayTracer;
    private final SamplingConfig antiAliasing, apertureSampling;
    private final int nX, nY;
    private final long seed;
    private final double pixelWidth, pixelHeight;
    private final boolean lens;
    private final double apertureRadius, focalDistance, vpDistance;
    private final Point location;
    private final Vector vTo, vRight, vUp;
    /** GRID offsets are the same in every pixel: computed once. */
    private final double[] gridOffsets;

    private final int adaptiveDepth;

    /** The sampling of {@code camera}'s next render, with its current settings. */
    PixelSampler(Camera camera) {
        this.camera = camera;
        rayTracer = camera.getRayTracer();
        antiAliasing = camera.getSamplingConfig();
        apertureSampling = camera.getApertureSampling();
        nX = camera.getNx();
        nY = camera.getNy();
        seed = rayTracer.getScene().getSeed();
        pixelWidth = camera.getVpWidth() / nX;
        pixelHeight = camera.getVpHeight() / nY;
        boolean planning = camera.getRenderSettings().planEffects();
        apertureRadius = camera.getApertureRadius();
        focalDistance = camera.getFocalDistance();
        vpDistance = camera.getVpDistance();
        lens = apertureRadius > 0 || (!planning && focalDistance > 0);
        location = camera.getLocation();
        vTo = camera.getDirection();
        vRight = camera.right();
        vUp = camera.getUp();
        gridOffsets = antiAliasing.getPattern() == SamplingPattern.GRID
                ? SuperSamplingBlackboard.getSampleOffsets(antiAliasing, new SampleStream(0))
                : null;
        adaptiveDepth = adaptiveDepth(antiAliasing);
    }

    /** Renders pixel (x, y) into {@code ctx.red, green, blue}. */
    void render(int x, int y, TraceContext ctx) {
        long pixelSeed = SampleStream.mix(seed, (long) y * nX + x);
        double u = centreU(x), v = centreV(y);
        int count = antiAliasing.getSampleCount();
        if (count == 1) {
            sample(u, v, pixelSeed, ctx);
            return;
        }
        if (antiAliasing.isAdaptive() && adaptiveDepth > 0) {
            adaptive(u, v, pixelSeed, ctx);
            return;
        }
        double[] offsets = gridOffsets;
        if (offsets == null) {
            offsets = ctx.pixelOffsets(count);
            SuperSamplingBlackboard.getSampleOffsets(
                    count,
                    antiAliasing.getShape(),
                    antiAliasing.getPattern(),
                    ctx.random.reset(SampleStream.mix(pixelSeed, AA_STREAM)),
                    offsets);
        }
        ColorAverage average = ctx.pixelAverage.reset();
        for (int s = 0; s < count; s++) {
            sample(
                    u + offsets[2 * s] * pixelWidth,
                    v + offsets[2 * s + 1] * pixelHeight,
                    SampleStream.mix(pixelSeed, s),
                    ctx);
            average.add(ctx);
        }
        average.meanInto(ctx);
    }

    /** The view-plane coordinate of the centre of pixel column {@code x}, rightward from the view's centre. */
    private double centreU(int x) {
        return (x - (nX - 1) / 2.0) * pixelWidth;
    }

    /** The view-plane coordinate of the centre of pixel row {@code y}, upward from the view's centre. */
    private double centreV(int y) {
        return -(y - (nY - 1) / 2.0) * pixelHeight;
    }

    /** Whether progressive samples spread over the pixel's area (anti-aliasing asked) or all go through its centre. */
    boolean samplesArea() {
        return antiAliasing.getSampleCount() > 1;
    }

    /**
     * Sample {@code index} of half {@code half} (0 or 1) of pixel (x, y) for progressive sampling with one camera ray
     * per pixel asked, into {@code ctx.red, green, blue}: the ray through the pixel's centre, with effect samples
     * (shadow, lens, glossy rays) of its own. {@code again} says that the previous sample this context took was of
     * the same pixel, so that a pinhole camera's first hit can be reused. (Samples over the pixel's area:
     * {@link #progressiveArea}.)
     */
    void progressiveSample(int x, int y, int half, int index, boolean again, TraceContext ctx) {
        beginProgressive(x, y, half, index, ctx);
        long path = pathSeed(ctx.progressivePixelSeed, half, index);
        // After the first sample, the pinhole's ray (still in ctx.cameraRay) and its first hit are the same, and are
        // reused.
        if (again && pinholeCentre()) rayTracer.traceAgain(ctx.cameraRay, ctx, path);
        else sample(centreU(x), centreV(y), path, ctx);
        ctx.sequenceIndex = -1;
    }

    /**
     * Samples {@code first} to {@code first + count - 1} of half {@code half} of pixel (x, y) over the pixel's area,
     * into the half's sums at {@code sums[o]} (red, green, blue), each colour added in turn: the Halton points of those
     * indices over the pixel, shifted by the half's own random offset (Cranley-Patterson rotation), so that the two
     * halves are independent low-discrepancy estimates of the pixel; or, where the context asks ({@code sobolArea}),
     * the {@link Sobol2D} points, digitally shifted by that offset's bits. One loop, not a call per sample: the
     * anti-aliasing experiment's progressive renders, warm, about 0.955x the time.
     */
    void progressiveArea(int x, int y, int half, int first, int count, double[] sums, int o, TraceContext ctx) {
        beginProgressive(x, y, half, first, ctx);
        double u = centreU(x), v = centreV(y);
        double shiftX = ctx.halfShifts[2 * half], shiftY = ctx.halfShifts[2 * half + 1];
        long pixelSeed = ctx.progressivePixelSeed;
        boolean sobol = ctx.sobolArea;
        int sobolX = Sobol2D.shift(shiftX), sobolY = Sobol2D.shift(shiftY);
        for (int index = first, end = first + count; index < end; index++) {
            ctx.sequenceIndex = index;
            double ox, oy;
            if (sobol) {
                ox = Sobol2D.x(index, sobolX);
                oy = Sobol2D.y(index, sobolY);
            } else {
                ox = SuperSamplingBlackboard.radicalInverse2(index + 1) + shiftX;
                oy = SuperSamplingBlackboard.radicalInverse(3, index + 1) + shiftY;
                if (ox >= 1) ox -= 1;
                if (oy >= 1) oy -= 1;
            }
            sample(u + (ox - 0.5) * pixelWidth, v - (oy - 0.5) * pixelHeight, pathSeed(pixelSeed, half, index), ctx);
            sums[o] += ctx.red;
            sums[o + 1] += ctx.green;
            sums[o + 2] += ctx.blue;
        }
        ctx.sequenceIndex = -1;
    }

    /**
     * For a pass of progressive samples through the centre of pixel (x, y) with a pinhole camera: fires its camera ray
     * and keeps the first hit, unshaded, so that every sample of the pass shades it again ({@code again}); returns
     * false, having done nothing, for samples over the pixel's area, through a lens, or a tracer that cannot.
     */
    boolean locateCentre(int x, int y, TraceContext ctx) {
        if (!pinholeCentre()) return false;
        double u = centreU(x), v = centreV(y);
        if (!rayTracer.locate(camera.rayThrough(u, v, ctx.cameraRay), ctx)) return false;
        ctx.counters.camera++;
        return true;
    }

    /**
     * Samples {@code first} to {@code first + count - 1} of half {@code half} of pixel (x, y) at once, the previous
     * sample this context took having been of the same pixel: the sum of their colours into {@code ctx.red, green,
     * blue}, where the tracer can shade the reused first hit once with all their shadow rays
     * ({@link RayTracerBase#traceAgainBatch}: centre samples of a pinhole camera). Returns false, having sampled
     * nothing, where it cannot.
     */
    boolean progressiveBatch(int x, int y, int half, int first, int count, TraceContext ctx) {
        if (count < 2 || !pinholeCentre()) return false;
        beginProgressive(x, y, half, first, ctx);
        long path = pathSeed(ctx.progressivePixelSeed, half, first);
        boolean shaded = rayTracer.traceAgainBatch(ctx.cameraRay, ctx, path, count);
        ctx.sequenceIndex = -1;
        if (shaded) ctx.setColor(ctx.red * count, ctx.green * count, ctx.blue * count);
        return shaded;
    }

    /** Whether every progressive sample goes through the pixel's centre from a pinhole: one camera ray serves them. */
    private boolean pinholeCentre() {
        return antiAliasing.getSampleCount() == 1 && !lens;
    }

    /**
     * Points the context at sample {@code index} of half {@code half} of pixel (x, y): the pixel's and halves' seeds
     * (per pixel, not per sample) and the half's sequence (its path seed: {@link #pathSeed}).
     */
    private void beginProgressive(int x, int y, int half, int index, TraceContext ctx) {
        int pixel = y * nX + x;
        if (ctx.progressivePixel != pixel) {
            long pixelSeed = SampleStream.mix(seed, pixel);
            ctx.progressivePixel = pixel;
            ctx.progressivePixelSeed = pixelSeed;
            boolean area = samplesArea();
            for (int h = 0; h < 2; h++) {
                long halfSeed = SampleStream.mix(pixelSeed, PROGRESSIVE_SHIFT + h);
                ctx.halfSeeds[h] = halfSeed;
                if (!area) continue; // the shifts place samples over the area; through the centre they are not used
                SampleStream shift = ctx.random.reset(halfSeed);
                ctx.halfShifts[2 * h] = shift.nextDouble();
                ctx.halfShifts[2 * h + 1] = shift.nextDouble();
            }
        }
        ctx.sequenceIndex = index;
        ctx.sequenceSeed = ctx.halfSeeds[half];
    }

    /** The path seed of sample {@code index} of half {@code half} of the pixel whose seed is {@code pixelSeed}. */
    private static long pathSeed(long pixelSeed, int half, int index) {
        return SampleStream.mix(pixelSeed, PROGRESSIVE_PATHS + 2L * index + half);
    }

    /**
     * One pixel sample at view-plane point (u, v), a pinhole ray or a beam over the lens; the colour is left in
     * {@code ctx.red, green, blue}.
     */
    private void sample(double u, double v, long path, TraceContext ctx) {
        if (!lens) {
            ctx.counters.camera++;
            rayTracer.trace(camera.rayThrough(u, v, ctx.cameraRay), ctx, path);
            return;
        }
        int count = apertureSampling.getSampleCount();
        double[] offsets = ctx.lensOffsets(count);
        if (!ctx.continueSequence(LENS_STREAM, count, TargetShape.CIRCLE, offsets)) {
            SuperSamplingBlackboard.getSampleOffsets(
                    count,
                    TargetShape.CIRCLE,
                    apertureSampling.getPattern(),
                    ctx.random.reset(SampleStream.mix(path, LENS_STREAM)),
                    offsets);
        }
        // The focal point of this sample: where its pinhole ray meets the focal plane.
        double scale = focalDistance / vpDistance;
        double fx = location.x + scale * (vpDistance * vTo.x + u * vRight.x + v * vUp.x);
        double fy = location.y + scale * (vpDistance * vTo.y + u * vRight.y + v * vUp.y);
        double fz = location.z + scale * (vpDistance * vTo.z + u * vRight.z + v * vUp.z);
        double diameter = 2 * apertureRadius;
        ColorAverage average = ctx.lensAverage.reset();
        for (int i = 0; i < count; i++) {
            double a = offsets[2 * i] * diameter, b = offsets[2 * i + 1] * diameter;
            double ox = location.x + a * vRight.x + b * vUp.x;
            double oy = location.y + a * vRight.y + b * vUp.y;
            double oz = location.z + a * vRight.z + b * vUp.z;
            Ray ray = ctx.cameraRay.set(ox, oy, oz, fx - ox, fy - oy, fz - oz);
            ctx.counters.camera++;
            ctx.counters.depthOfField++;
            // A zero aperture (planning off) fires identical rays: same path, so the mean is exact.
            rayTracer.trace(ray, ctx, apertureRadius > 0 ? SampleStream.mix(path, i) : path);
            average.add(ctx);
        }
        average.meanInto(ctx);
    }

    /**
     * Adaptive anti-aliasing: colours at the corners of the pixel, subdivided into quadrants where they differ
     * by more than the threshold, down to a lattice of (2^depth + 1)^2 points that is never exceeded. The lattice
     * and the quadrants' averages are the thread's ({@link TraceContext#lattice}), so a pixel allocates nothing;
     * the mean is left in {@code ctx.red, green, blue}.
     */
    private void adaptive(double u, double v, long pixelSeed, TraceContext ctx) {
        int side = (1 << adaptiveDepth) + 1;
        TraceContext.Lattice lattice = ctx.lattice(side * side);
        quadrant(0, 0, side - 1, u, v, pixelSeed, lattice, side, 0, ctx);
        int fired = 0;
        for (int k = 0, n = side * side; k < n; k++) if (lattice.filled[k]) fired++;
        ctx.counters.samplesSaved += antiAliasing.getSampleCount() - fired;
    }

    /** The mean of a quadrant into {@code ctx}; {@code level} picks the average of this depth of the recursion. */
    private void quadrant(
            int i0,
            int j0,
            int size,
            double u,
            double v,
            long seed,
            TraceContext.Lattice lattice,
            int side,
            int level,
            TraceContext ctx) {
        int k00 = latticeSample(i0, j0, u, v, seed, lattice, side, ctx);
        int k10 = latticeSample(i0 + size, j0, u, v, seed, lattice, side, ctx);
        int k01 = latticeSample(i0, j0 + size, u, v, seed, lattice, side, ctx);
        int k11 = latticeSample(i0 + size, j0 + size, u, v, seed, lattice, side, ctx);
        ColorAverage a = lattice.average(level).reset();
        if (size == 1 || maxDifference(lattice, k00, k10, k01, k11) <= antiAliasing.getAdaptiveThreshold()) {
            a.add(lattice.r[k00], lattice.g[k00], lattice.b[k00]);
            a.add(lattice.r[k10], lattice.g[k10], lattice.b[k10]);
            a.add(lattice.r[k01], lattice.g[k01], lattice.b[k01]);
            a.add(lattice.r[k11], lattice.g[k11], lattice.b[k11]);
            a.meanInto(ctx);
            return;
        }
        int half = size / 2;
        quadrant(i0, j0, half, u, v, seed, lattice, side, level + 1, ctx);
        a.add(ctx);
        quadrant(i0 + half, j0, half, u, v, seed, lattice, side, level + 1, ctx);
        a.add(ctx);
        quadrant(i0, j0 + half, half, u, v, seed, lattice, side, level + 1, ctx);
        a.add(ctx);
        quadrant(i0 + half, j0 + half, half, u, v, seed, lattice, side, level + 1, ctx);
        a.add(ctx);
        a.meanInto(ctx);
    }

    /** The lattice point (i, j), sampled on first use; returns its index into the lattice. */
    private int latticeSample(
            int i, int j, double u, double v, long seed, TraceContext.Lattice lattice, int side, TraceContext ctx) {
        int index = j * side + i;
        if (!lattice.filled[index]) {
            // Lattice points at the centres of a side x side grid of cells, not on the pixel's border: fully
            // refined, the lattice is the GRID pattern of side^2 samples (a box filter over this pixel alone);
            // points on the border would also be samples of the neighbouring pixels and blur the image.
            double du = ((i + 0.5) / side - 0.5) * pixelWidth;
            double dv = ((j + 0.5) / side - 0.5) * pixelHeight;
            sample(u + du, v - dv, SampleStream.mix(seed, ADAPTIVE_PATHS + index), ctx);
            lattice.r[index] = ctx.red;
            lattice.g[index] = ctx.green;
            lattice.b[index] = ctx.blue;
            lattice.filled[index] = true;
        }
        return index;
    }

    /** Deepest subdivision whose lattice of (2^d + 1)^2 points fits the sample budget. */
    private static int adaptiveDepth(SamplingConfig config) {
        int depth = 0;
        while (depth < 10) {
            long side = (1L << (depth + 1)) + 1;
            if (side * side > config.getSampleCount()) break;
            depth++;
        }
        return depth;
    }

    /** The largest difference of one channel between any two of four lattice points. */
    private static double maxDifference(TraceContext.Lattice l, int k0, int k1, int k2, int k3) {
        double max = 0;
        max = Math.max(max, difference(l, k0, k1));
        max = Math.max(max, difference(l, k0, k2));
        max = Math.max(max, difference(l, k0, k3));
        max = Math.max(max, difference(l, k1, k2));
        max = Math.max(max, difference(l, k1, k3));
        return Math.max(max, difference(l, k2, k3));
    }

    private static double difference(TraceContext.Lattice l, int a, int b) {
        return Math.max(Math.abs(l.r[a] - l.r[b]), Math.max(Math.abs(l.g[a] - l.g[b]), Math.abs(l.b[a] - l.b[b])));
    }
}
