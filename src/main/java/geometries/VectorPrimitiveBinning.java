package geometries;

import static geometries.BVH.BOX_MAX;
import static geometries.BVH.BOX_STRIDE;
import static geometries.SahSplitter.CENTROID_MAX;
import static geometries.SahSplitter.CENTROID_MIN;
import static geometries.SahSplitter.MAX;
import static geometries.SahSplitter.MIN;
import static geometries.SahSplitter.SUMMARY;
import static jdk.incubator.vector.VectorOperators.F2D;
import static jdk.incubator.vector.VectorOperators.GT;
import static jdk.incubator.vector.VectorOperators.LT;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorSpecies;

/**
 * {@link PrimitiveBinning} on the JDK's incubating Vector API: a box's minimum corner and maximum corner are each
 * one load of four floats widened to four doubles, its centroid their sum halved, and a run's or a bin's summary
 * four vector minima and maxima instead of twelve scalar ones (the sequential binary tree of the 1M heightfield
 * 0.364-0.366 -> 0.303-0.327 s, best of 15, alternated with the scalar binning). A run's minima and maxima are a
 * comparison and a blend each, which on the inputs {@link PrimitiveBinning#bin} allows are {@link Math#min}'s and
 * {@link Math#max}'s (0.199-0.273 -> 0.177-0.189 s against lanewise MIN and MAX, which follow them on any input, five
 * alternated pairs); summaries and merges, which take any input, keep lanewise MIN and MAX. The centroid is the same
 * double sum as the scalar code's, so the bins are identical. Loaded only when the JVM runs with {@code --add-modules
 * jdk.incubator.vector}.
 */
final class VectorPrimitiveBinning extends PrimitiveBinning {
    private static final VectorSpecies<Float> CORNER = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> WIDE = DoubleVector.SPECIES_256;

    /** Refuses (and the scalar binning runs) where the CPU has no 256-bit vectors, as {@link VectorWideBoxTest}. */
    VectorPrimitiveBinning() {
        if (FloatVector.SPECIES_PREFERRED.vectorBitSize() < 256) {
            throw new UnsupportedOperationException("no 256-bit vectors on this CPU");
        }
    }

    @Override
    String name() {
        return "vector";
    }

    /**
     * Written out in one method, with the run's flush twice: no vector crosses a call the JIT might not inline (which
     * would box it), as in {@link VectorWideBoxTest}. The flush as a helper measured level in two runs of three and
     * 0.548 s against 0.234 s in the third (the sequential tree of the 1M heightfield, best of 15).
     */
    @Override
    void bin(float[] boxes, int[] index, int start, int end, int axis, double lo, double scale, SahBins bins) {
        int size = bins.size();
        double[] s = bins.summaries;
        int[] count = bins.count;
        byte[] binOfPosition = bins.binOfPosition;
        // Neighbours in the index mostly fall in the same bin: a run of them is summarized in registers and merged
        // into its bin once.
        int runBin = -1, run = 0;
        DoubleVector runMin = DoubleVector.zero(WIDE), runMax = runMin, runCentroidMin = runMin;
        DoubleVector runCentroidMax = runMin;
        for (int k = start; k < end; k++) {
            int o = BOX_STRIDE * index[k];
            // Each corner is four floats widened to four doubles, written out here rather than in a helper (see above).
            DoubleVector min =
                    (DoubleVector) FloatVector.fromArray(CORNER, boxes, o).convertShape(F2D, WIDE, 0);
            DoubleVector max = (DoubleVector)
                    FloatVector.fromArray(CORNER, boxes, o + BOX_MAX).convertShape(F2D, WIDE, 0);
            DoubleVector centroid = min.add(max).mul(0.5);
            // The centroid on the axis from the floats again: a lane picked by a variable index costs more.
            int bin = binOf(0.5 * ((double) boxes[o + axis] + boxes[o + BOX_MAX + axis]), lo, scale, size);
            binOfPosition[k - start] = (byte) bin;
            if (bin == runBin) {
                run++;
                runMin = runMin.blend(min, min.compare(LT, runMin));
                runMax = runMax.blend(max, max.compare(GT, runMax));
                runCentroidMin = runCentroidMin.blend(centroid, centroid.compare(LT, runCentroidMin));
                runCentroidMax = runCentroidMax.blend(centroid, centroid.compare(GT, runCentroidMax));
                continue;
            }
            if (run > 0) {
                int b = SUMMARY * runBin;
                if (count[runBin] == 0) {
                    bins.used[bins.usedCount++] = runBin;
                    runMin.intoArray(s, b + MIN);
                    runMax.intoArray(s, b + MAX);
                    runCentroidMin.intoArray(s, b + CENTROID_MIN);
                    runCentroidMax.intoArray(s, b + CENTROID_MAX);
                } else {
                    DoubleVector.fromArray(WIDE, s, b + MIN).min(runMin).intoArray(s, b + MIN);
                    DoubleVector.fromArray(WIDE, s, b + MAX).max(runMax).intoArray(s, b + MAX);
                    DoubleVector.fromArray(WIDE, s, b + CENTROID_MIN)
                            .min(runCentroidMin)
                            .intoArray(s, b + CENTROID_MIN);
                    DoubleVector.fromArray(WIDE, s, b + CENTROID_MAX)
                            .max(runCentroidMax)
                            .intoArray(s, b + CENTROID_MAX);
                }
                count[runBin] += run;
            }
            runBin = bin;
            run = 1;
            runMin = min;
            runMax = max;
            runCentroidMin = centroid;
            runCentroidMax = centroid;
        }
        if (run > 0) {
            int b = SUMMARY * runBin;
            if (count[runBin] == 0) {
                bins.used[bins.usedCount++] = runBin;
                runMin.intoArray(s, b + MIN);
                runMax.intoArray(s, b + MAX);
                runCentroidMin.intoArray(s, b + CENTROID_MIN);
                runCentroidMax.intoArray(s, b + CENTROID_MAX);
            } else {
                DoubleVector.fromArray(WIDE, s, b + MIN).min(runMin).intoArray(s, b + MIN);
                DoubleVector.fromArray(WIDE, s, b + MAX).max(runMax).intoArray(s, b + MAX);
                DoubleVector.fromArray(WIDE, s, b + CENTROID_MIN)
                        .min(runCentroidMin)
                        .intoArray(s, b + CENTROID_MIN);
                DoubleVector.fromArray(WIDE, s, b + CENTROID_MAX)
                        .max(runCentroidMax)
                        .intoArray(s, b + CENTROID_MAX);
            }
            count[runBin] += run;
        }
    }

    @Override
    void summarize(float[] boxes, int[] index, int start, int end, double[] s, int at) {
        DoubleVector min = DoubleVector.broadcast(WIDE, Double.POSITIVE_INFINITY), centroidMin = min;
        DoubleVector max = DoubleVector.broadcast(WIDE, Double.NEGATIVE_INFINITY), centroidMax = max;
        for (int k = start; k < end; k++) {
            int o = BOX_STRIDE * index[k];
            DoubleVector lo =
                    (DoubleVector) FloatVector.fromArray(CORNER, boxes, o).convertShape(F2D, WIDE, 0);
            DoubleVector hi = (DoubleVector)
                    FloatVector.fromArray(CORNER, boxes, o + BOX_MAX).convertShape(F2D, WIDE, 0);
            DoubleVector centroid = lo.add(hi).mul(0.5);
            min = min.min(lo);
            max = max.max(hi);
            centroidMin = centroidMin.min(centroid);
            centroidMax = centroidMax.max(centroid);
        }
        min.intoArray(s, at + MIN);
        max.intoArray(s, at + MAX);
        centroidMin.intoArray(s, at + CENTROID_MIN);
        centroidMax.intoArray(s, at + CENTROID_MAX);
    }

    @Override
    void merge(double[] from, int f, double[] to, int t) {
        DoubleVector.fromArray(WIDE, to, t + MIN)
                .min(DoubleVector.fromArray(WIDE, from, f + MIN))
                .intoArray(to, t + MIN);
        DoubleVector.fromArray(WIDE, to, t + MAX)
                .max(DoubleVector.fromArray(WIDE, from, f + MAX))
                .intoArray(to, t + MAX);
        DoubleVector.fromArray(WIDE, to, t + CENTROID_MIN)
                .min(DoubleVector.fromArray(WIDE, from, f + CENTROID_MIN))
                .intoArray(to, t + CENTROID_MIN);
        DoubleVector.fromArray(WIDE, to, t + CENTROID_MAX)
                .max(DoubleVector.fromArray(WIDE, from, f + CENTROID_MAX))
                .intoArray(to, t + CENTROID_MAX);
    }
}
