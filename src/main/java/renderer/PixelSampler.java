package renderer;

import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.sampling.SampleStream;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.SuperSamplingBlackboard;
import renderer.sampling.TargetShape;

/**
 * A camera's pixel sampling for one render: one ray through the pixel's centre or a beam over the pixel's area
 * (anti-aliasing, fixed or adaptive by corner subdivision), and with an aperture a beam over the lens for every
 * sample (depth of field). Every random number derives from the scene seed and the pixel's index, so a pixel's
 * colour does not depend on the thread or the order that renders it. The {@link Camera} keeps the view's geometry,
 * the tiles and the threads.
 */
final class PixelSampler {
    private static final long AA_STREAM = 11, LENS_STREAM = 12, ADAPTIVE_PATHS = 1L << 40;

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
        double u = (x - (nX - 1) / 2.0) * pixelWidth;
        double v = -(y - (nY - 1) / 2.0) * pixelHeight;
        int count = antiAliasing.getSampleCount();
        if (count == 1) {
            sample(u, v, pixelSeed, ctx);
            return;
        }
        if (antiAliasing.isAdaptive() && adaptiveDepth > 0) {
            Color c = adaptive(u, v, pixelSeed, ctx);
            ctx.setColor(c.getR(), c.getG(), c.getB());
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

    /**
     * One pixel sample at view-plane point (u, v), a pinhole ray or a beam over the lens; the colour is left in
     * {@code ctx.red, green, blue}.
     */
    private void sample(double u, double v, long path, TraceContext ctx) {
        if (!lens) {
            ctx.counters.camera++;
            rayTracer.trace(camera.rayThrough(u, v, ctx.ray), ctx, path);
            return;
        }
        int count = apertureSampling.getSampleCount();
        double[] offsets = ctx.lensOffsets(count);
        SuperSamplingBlackboard.getSampleOffsets(
                count,
                TargetShape.CIRCLE,
                apertureSampling.getPattern(),
                ctx.random.reset(SampleStream.mix(path, LENS_STREAM)),
                offsets);
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
            Ray ray = ctx.ray.set(ox, oy, oz, fx - ox, fy - oy, fz - oz);
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
     * by more than the threshold, down to a lattice of (2^depth + 1)^2 points that is never exceeded.
     */
    private Color adaptive(double u, double v, long pixelSeed, TraceContext ctx) {
        int side = (1 << adaptiveDepth) + 1;
        Color[] cache = new Color[side * side];
        Color c = quadrant(0, 0, side - 1, u, v, pixelSeed, cache, side, ctx);
        int fired = 0;
        for (Color cached : cache) if (cached != null) fired++;
        ctx.counters.samplesSaved += antiAliasing.getSampleCount() - fired;
        return c;
    }

    private Color quadrant(
            int i0, int j0, int size, double u, double v, long seed, Color[] cache, int side, TraceContext ctx) {
        Color c00 = latticeSample(i0, j0, u, v, seed, cache, side, ctx);
        Color c10 = latticeSample(i0 + size, j0, u, v, seed, cache, side, ctx);
        Color c01 = latticeSample(i0, j0 + size, u, v, seed, cache, side, ctx);
        Color c11 = latticeSample(i0 + size, j0 + size, u, v, seed, cache, side, ctx);
        if (size == 1 || maxDifference(c00, c10, c01, c11) <= antiAliasing.getAdaptiveThreshold()) {
            ColorAverage a = new ColorAverage();
            a.add(c00);
            a.add(c10);
            a.add(c01);
            a.add(c11);
            return a.mean();
        }
        int half = size / 2;
        ColorAverage a = new ColorAverage();
        a.add(quadrant(i0, j0, half, u, v, seed, cache, side, ctx));
        a.add(quadrant(i0 + half, j0, half, u, v, seed, cache, side, ctx));
        a.add(quadrant(i0, j0 + half, half, u, v, seed, cache, side, ctx));
        a.add(quadrant(i0 + half, j0 + half, half, u, v, seed, cache, side, ctx));
        return a.mean();
    }

    private Color latticeSample(
            int i, int j, double u, double v, long seed, Color[] cache, int side, TraceContext ctx) {
        int index = j * side + i;
        Color c = cache[index];
        if (c == null) {
            // Lattice points at the centres of a side x side grid of cells, not on the pixel's border: fully
            // refined, the lattice is the GRID pattern of side^2 samples (a box filter over this pixel alone);
            // points on the border would also be samples of the neighbouring pixels and blur the image.
            double du = ((i + 0.5) / side - 0.5) * pixelWidth;
            double dv = ((j + 0.5) / side - 0.5) * pixelHeight;
            sample(u + du, v - dv, SampleStream.mix(seed, ADAPTIVE_PATHS + index), ctx);
            c = ctx.color();
            cache[index] = c;
        }
        return c;
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

    private static double maxDifference(Color... colors) {
        double max = 0;
        for (int a = 0; a < colors.length; a++) {
            for (int b = a + 1; b < colors.length; b++) {
                max = Math.max(max, Math.abs(colors[a].getR() - colors[b].getR()));
                max = Math.max(max, Math.abs(colors[a].getG() - colors[b].getG()));
                max = Math.max(max, Math.abs(colors[a].getB() - colors[b].getB()));
            }
        }
        return max;
    }
}
