package geometries;

import static geometries.BVH.BOX_MAX;
import static geometries.BVH.BOX_STRIDE;
import static geometries.SahSplitter.CENTROID_MAX;
import static geometries.SahSplitter.CENTROID_MIN;
import static geometries.SahSplitter.MAX;
import static geometries.SahSplitter.MIN;
import static geometries.SahSplitter.SUMMARY;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.SplittableRandom;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The two implementations of {@link PrimitiveBinning}: the JVM picks the vectorized one exactly when the Vector API
 * module is present (surefire runs this class both with and without it); the one it runs puts every primitive in the
 * bin of its centroid with exactly its members' boxes and centroids; and both give the same bins, summaries and
 * merges bit for bit, on random boxes mixed with the hard ones: flat, signed zeros, at float's largest value, and
 * infinite (whose centroids are infinite or NaN), binning them as a build gives them to it (no -0.0; a range spanning an
 * axis from -inf to +inf binned by the scalar code).
 */
class PrimitiveBinningTest {
    @Test
    void theVectorizedBinningRunsExactlyWhenTheModuleIsPresent() throws ReflectiveOperationException {
        assertEquals(
                VectorSupport.available() ? "vector" : "scalar",
                PrimitiveBinning.selected().name());
    }

    static LongStream seeds() {
        return LongStream.range(0, 12).map(i -> 0x5A4B1 + 7919 * i);
    }

    /** Each bin holds the primitives whose centroids fall in it, its summary exactly theirs. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void everyPrimitiveLandsInItsBinWithItsBox(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int n = 1 + random.nextInt(3000);
        float[] boxes = binnable(randomBoxes(n, random, false));
        int[] index = shuffled(n, random);
        int start = random.nextInt(n), end = start + 1 + random.nextInt(n - start);
        int axis = random.nextInt(3), size = 2 + random.nextInt(31);
        double[] whole = new double[SUMMARY];
        PrimitiveBinning.selected().summarize(boxes, index, start, end, whole, 0);
        double lo = whole[CENTROID_MIN + axis];
        double extent = whole[CENTROID_MAX + axis] - lo;
        double scale = extent > 0 ? size / extent : 1;
        SahBins bins = new SahBins(size);
        bins.clear(end - start);
        PrimitiveBinning.selected().bin(boxes, index, start, end, axis, lo, scale, bins);

        int[] count = new int[size];
        double[] expected = new double[SUMMARY * size];
        for (int b = 0; b < size; b++) SahSplitter.resetSummary(expected, SUMMARY * b);
        for (int k = start; k < end; k++) {
            int o = BOX_STRIDE * index[k];
            double c = 0.5 * ((double) boxes[o + axis] + boxes[o + BOX_MAX + axis]);
            int bin = PrimitiveBinning.binOf(c, lo, scale, size);
            assertEquals(bin, bins.binOfPosition[k - start] & 0xFF, "bin recorded at position " + (k - start));
            count[bin]++;
            for (int a = 0; a < 3; a++) {
                double min = boxes[o + a], max = boxes[o + BOX_MAX + a], centroid = 0.5 * (min + max);
                int e = SUMMARY * bin;
                expected[e + MIN + a] = Math.min(expected[e + MIN + a], min);
                expected[e + MAX + a] = Math.max(expected[e + MAX + a], max);
                expected[e + CENTROID_MIN + a] = Math.min(expected[e + CENTROID_MIN + a], centroid);
                expected[e + CENTROID_MAX + a] = Math.max(expected[e + CENTROID_MAX + a], centroid);
            }
        }
        int used = 0;
        for (int b = 0; b < size; b++) {
            assertEquals(count[b], bins.count[b], "bin " + b);
            if (count[b] > 0) {
                used++;
                assertSameSummary(expected, SUMMARY * b, bins.summaries, SUMMARY * b, "bin " + b);
            }
        }
        assertEquals(used, bins.usedCount, "bins listed as used");
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void scalarAndVectorBinningAgree(long seed) throws ReflectiveOperationException {
        assumeTrue(VectorSupport.available(), "needs --add-modules jdk.incubator.vector and 256-bit vectors");
        PrimitiveBinning vector = (PrimitiveBinning) Class.forName("geometries.VectorPrimitiveBinning")
                .getDeclaredConstructor()
                .newInstance();
        PrimitiveBinning scalar = new ScalarPrimitiveBinning();
        SplittableRandom random = new SplittableRandom(seed);
        int n = 1 + random.nextInt(3000);
        // Half the seeds draw every bound from a few values, so that ties between signed zeros, and infinite and NaN
        // centroids, meet in the same runs and bins.
        float[] boxes = seed % 2 == 0 ? randomBoxes(n, random, true) : boxesOfFewValues(n, random);
        int[] index = shuffled(n, random);
        // Binning needs the boxes as a build gives it them; summaries and merges take any.
        float[] binnable = binnable(boxes);
        for (int round = 0; round < 20; round++) {
            // Short ranges too: over many primitives a tie between zeros rarely decides a minimum or maximum.
            int start = random.nextInt(n);
            int length = random.nextBoolean() ? random.nextInt(9) : random.nextInt(n - start + 1);
            int end = Math.min(n, start + length);
            double[] s = new double[SUMMARY], v = new double[SUMMARY];
            scalar.summarize(boxes, index, start, end, s, 0);
            vector.summarize(boxes, index, start, end, v, 0);
            assertSameSummary(s, 0, v, 0, "summary of [" + start + ", " + end + ")");

            int axis = random.nextInt(3), size = 2 + random.nextInt(31);
            double lo = random.nextInt(4) == 0 ? s[CENTROID_MIN + axis] : 100 * random.nextGaussian();
            double scale = random.nextInt(4) == 0 ? 0.0 : Math.exp(6 * random.nextGaussian());
            SahBins a = new SahBins(size), b = new SahBins(size);
            a.clear(end - start);
            b.clear(end - start);
            scalar.bin(binnable, index, start, end, axis, lo, scale, a);
            vector.bin(binnable, index, start, end, axis, lo, scale, b);
            assertEquals(a.usedCount, b.usedCount, "bins used");
            for (int k = 0; k < end - start; k++) {
                assertEquals(a.binOfPosition[k], b.binOfPosition[k], "bin recorded at position " + k);
            }
            for (int u = 0; u < a.usedCount; u++) {
                int bin = a.used[u];
                assertEquals(bin, b.used[u], "bins in the order first used");
                assertEquals(a.count[bin], b.count[bin], "count of bin " + bin);
                assertSameSummary(a.summaries, SUMMARY * bin, b.summaries, SUMMARY * bin, "bin " + bin);
            }

            double[] into = new double[SUMMARY];
            SahSplitter.resetSummary(into, 0);
            double[] other = into.clone();
            for (int u = 0; u < a.usedCount; u++) {
                scalar.merge(a.summaries, SUMMARY * a.used[u], into, 0);
                vector.merge(b.summaries, SUMMARY * b.used[u], other, 0);
            }
            assertSameSummary(into, 0, other, 0, "merged bins");
        }
    }

    /** A range whose box spans an axis from -inf to +inf (centroids there may be NaN) is binned by the scalar code. */
    @Test
    void aRangeSpanningAnAxisIsBinnedByTheScalarCode() {
        double[] summary = new double[2 * SUMMARY];
        for (int s = 0; s < 2; s++) {
            for (int a = 0; a < 3; a++) {
                summary[SUMMARY * s + MIN + a] = -1;
                summary[SUMMARY * s + MAX + a] = 1;
            }
        }
        summary[SUMMARY + MIN + 1] = Double.NEGATIVE_INFINITY;
        summary[SUMMARY + MAX + 1] = Double.POSITIVE_INFINITY;
        assertEquals(
                PrimitiveBinning.selected().name(),
                PrimitiveBinning.forBinning(4, summary, 0).name());
        assertEquals("scalar", PrimitiveBinning.forBinning(4, summary, SUMMARY).name());
        // Infinite on one side only: centroids there are infinite, not NaN, and any binning takes them.
        summary[SUMMARY + MAX + 1] = 1;
        assertEquals(
                PrimitiveBinning.selected().name(),
                PrimitiveBinning.forBinning(4, summary, SUMMARY).name());
    }

    /**
     * A build sets bounds at -0.0 to 0.0 (the vectorized binning's minima need no signed zeros): the tree is the one
     * built from the same boxes at 0.0, bit for bit.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aBuildReadsNegativeZeroAsZero(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int n = 1 + random.nextInt(400);
        float[] signed = new float[BOX_STRIDE * n];
        for (int p = 0; p < n; p++) {
            for (int a = 0; a < 3; a++) {
                boolean zero = random.nextInt(3) == 0;
                float lo = zero ? (random.nextBoolean() ? -0.0f : 0.0f) : (float) random.nextGaussian();
                float hi = zero && random.nextBoolean() ? -0.0f : Math.max(lo, 0) + (float) random.nextDouble();
                signed[BOX_STRIDE * p + a] = lo;
                signed[BOX_STRIDE * p + BOX_MAX + a] = hi;
            }
        }
        float[] unsigned = signed.clone();
        for (int i = 0; i < unsigned.length; i++) unsigned[i] += 0.0f;
        BVH fromSigned = BVH.build(signed, 16, 4, false, null), fromUnsigned = BVH.build(unsigned, 16, 4, false, null);
        assertArrayEquals(fromUnsigned.nodes, fromSigned.nodes);
        assertArrayEquals(fromUnsigned.order, fromSigned.order);
        for (float bound : signed) assertNotEquals(Float.floatToRawIntBits(-0.0f), Float.floatToRawIntBits(bound));
    }

    /**
     * The boxes as a build bins them: bounds at -0.0 set to 0.0 (as {@link BVH#build} sets them), and an axis spanning
     * -inf to +inf cut to float's largest negative value below (the build bins such ranges with the scalar code).
     */
    private static float[] binnable(float[] boxes) {
        float[] binnable = boxes.clone();
        for (int i = 0; i < binnable.length; i++) binnable[i] += 0.0f;
        for (int o = 0; o < binnable.length; o += BOX_STRIDE) {
            for (int a = 0; a < 3; a++) {
                if (binnable[o + a] == Float.NEGATIVE_INFINITY
                        && binnable[o + BOX_MAX + a] == Float.POSITIVE_INFINITY) {
                    binnable[o + a] = -Float.MAX_VALUE;
                }
            }
        }
        return binnable;
    }

    /** The twelve values of two summaries, bit for bit (any NaN equal to any NaN). */
    private static void assertSameSummary(double[] expected, int e, double[] actual, int a, String what) {
        for (int corner : new int[] {MIN, MAX, CENTROID_MIN, CENTROID_MAX}) {
            for (int i = 0; i < 3; i++) {
                assertEquals(
                        Double.doubleToLongBits(expected[e + corner + i]),
                        Double.doubleToLongBits(actual[a + corner + i]),
                        what + ", value " + (corner + i) + ": " + expected[e + corner + i] + " against "
                                + actual[a + corner + i]);
            }
        }
    }

    /**
     * Boxes of {@code n} primitives in the build's layout: mostly small random boxes, in runs along x as a mesh's
     * come, some flat, some with signed zeros, some at float's largest value; with {@code extreme}, some infinite.
     */
    private static float[] randomBoxes(int n, SplittableRandom random, boolean extreme) {
        float[] boxes = new float[BOX_STRIDE * n];
        double x = 0;
        for (int p = 0; p < n; p++) {
            x += random.nextDouble();
            int o = BOX_STRIDE * p, kind = random.nextInt(extreme ? 12 : 10);
            for (int a = 0; a < 3; a++) {
                float lo, hi;
                switch (kind) {
                    case 0 -> lo = hi = (float) random.nextGaussian(); // flat
                    case 1 -> {
                        lo = random.nextBoolean() ? 0.0f : -0.0f;
                        hi = random.nextBoolean() ? 0.0f : -0.0f;
                    }
                    case 2 -> {
                        lo = Float.MAX_VALUE * (random.nextBoolean() ? 1 : -1);
                        hi = Float.MAX_VALUE;
                    }
                    case 10 -> {
                        lo = random.nextBoolean() ? Float.NEGATIVE_INFINITY : (float) random.nextGaussian();
                        hi = Float.POSITIVE_INFINITY;
                    }
                    case 11 -> {
                        lo = Float.NEGATIVE_INFINITY;
                        hi = (float) random.nextGaussian();
                    }
                    default -> {
                        lo = (float) ((a == 0 ? x : 0) + 10 * random.nextGaussian());
                        hi = lo + (float) Math.abs(random.nextGaussian());
                    }
                }
                boxes[o + a] = lo;
                boxes[o + BOX_MAX + a] = hi;
            }
        }
        return boxes;
    }

    /** Boxes whose bounds are drawn from signed zeros (half of them), one, float's largest value and the infinities. */
    private static float[] boxesOfFewValues(int n, SplittableRandom random) {
        float[] values = {
            Float.NEGATIVE_INFINITY,
            -Float.MAX_VALUE,
            -1,
            -0.0f,
            -0.0f,
            -0.0f,
            0.0f,
            0.0f,
            0.0f,
            1,
            Float.MAX_VALUE,
            Float.POSITIVE_INFINITY
        };
        float[] boxes = new float[BOX_STRIDE * n];
        for (int p = 0; p < n; p++) {
            for (int a = 0; a < 3; a++) {
                int i = random.nextInt(values.length), j = random.nextInt(values.length);
                boxes[BOX_STRIDE * p + a] = values[Math.min(i, j)];
                boxes[BOX_STRIDE * p + BOX_MAX + a] = values[Math.max(i, j)];
            }
        }
        return boxes;
    }

    private static int[] shuffled(int n, SplittableRandom random) {
        int[] index = new int[n];
        for (int i = 0; i < n; i++) index[i] = i;
        // Mostly in order, as a mesh's primitives come: swap a few.
        for (int i = 0; i < n / 8; i++) {
            int a = random.nextInt(n), b = random.nextInt(n), t = index[a];
            index[a] = index[b];
            index[b] = t;
        }
        return index;
    }
}
