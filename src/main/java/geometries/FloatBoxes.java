package geometries;

import static geometries.BVH.BOX_MAX;
import static geometries.BVH.BOX_STRIDE;

/**
 * The primitive boxes a {@link BVH} build reads: floats, {@link BVH#BOX_STRIDE} per primitive (the minimum corner and
 * an unused fourth value, then the maximum corner likewise), each rounded outward from the doubles it came from so
 * that it still holds its primitive. Here they are made and checked: a box that is empty or NaN on some axis is
 * refused with the primitive and the axis named, since one such box would poison every box above it.
 */
final class FloatBoxes {
    /** Boxes per chunk of {@link #checkAndNormalize(float[], boolean)}. */
    private static final int CHECK_CHUNK = 1 << 16;

    private FloatBoxes() {}

    /**
     * Boxes given in doubles (six per primitive), each rounded outward to floats in the build's layout; a box empty or
     * NaN in doubles is refused here, since rounding could make a box empty by less than a float's step look valid.
     */
    static float[] roundedOutward(double[] bounds) {
        if (bounds.length % 6 != 0) {
            throw new IllegalArgumentException("primitive bounds must hold 6 values per primitive");
        }
        int n = bounds.length / 6;
        float[] rounded = new float[BOX_STRIDE * n];
        for (int p = 0; p < n; p++) {
            for (int a = 0; a < 3; a++) {
                double lo = bounds[6 * p + a], hi = bounds[6 * p + 3 + a];
                requireBox(p, a, lo, hi);
                rounded[BOX_STRIDE * p + a] = floatBelow(lo);
                rounded[BOX_STRIDE * p + BOX_MAX + a] = floatAbove(hi);
            }
        }
        return rounded;
    }

    /**
     * Checks every box of {@code boxes}, in chunks on all cores where there are many and {@code parallel} (one core
     * took 7 ms for a million), and sets their bounds at -0.0 to 0.0 in place (the same bound: the vectorized
     * binning's minima and maxima need no signed zeros).
     *
     * @throws IllegalArgumentException if the array is empty or not a whole number of boxes, or names the first box
     *     that is empty or NaN on some axis
     */
    static void checkAndNormalize(float[] boxes, boolean parallel) {
        if (boxes.length % BOX_STRIDE != 0) {
            throw new IllegalArgumentException("primitive bounds must hold " + BOX_STRIDE + " values per primitive");
        }
        if (boxes.length == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        int n = boxes.length / BOX_STRIDE;
        int[] firstBad = new int[BuildPool.chunks(n, CHECK_CHUNK)];
        BuildPool.forEachChunk(n, CHECK_CHUNK, parallel, (chunk, from, to) -> {
            firstBad[chunk] = checkAndNormalize(boxes, from, to);
        });
        // The first bad box of all: the first one found by the first chunk that found one.
        for (int bad : firstBad) {
            if (bad >= 0) {
                int b = BOX_STRIDE * bad;
                for (int a = 0; a < 3; a++) requireBox(bad, a, boxes[b + a], boxes[b + BOX_MAX + a]);
            }
        }
    }

    /**
     * Sets the bounds at -0.0 of boxes {@code [from, to)} to 0.0 and returns the first box that is empty or NaN on
     * some axis, or -1.
     */
    private static int checkAndNormalize(float[] boxes, int from, int to) {
        int firstBad = -1;
        for (int p = from; p < to; p++) {
            int b = BOX_STRIDE * p;
            for (int a = 0; a < 3; a++) {
                if (!(boxes[b + a] <= boxes[b + BOX_MAX + a]) && firstBad < 0) firstBad = p;
                boxes[b + a] += 0.0f;
                boxes[b + BOX_MAX + a] += 0.0f;
            }
        }
        return firstBad;
    }

    /** Throws unless {@code lo <= hi}, written so that NaN fails too. */
    private static void requireBox(int primitive, int axis, double lo, double hi) {
        if (!(lo <= hi)) {
            throw new IllegalArgumentException("primitive " + primitive + " has an empty or NaN box on axis " + axis
                    + ": [" + lo + ", " + hi + "]");
        }
    }

    /** The largest float not above {@code x}. */
    static float floatBelow(double x) {
        float f = (float) x;
        return f > x ? Math.nextDown(f) : f;
    }

    /** The smallest float not below {@code x}. */
    static float floatAbove(double x) {
        float f = (float) x;
        return f < x ? Math.nextUp(f) : f;
    }
}
