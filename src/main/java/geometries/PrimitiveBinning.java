package geometries;

/**
 * The loops of the SAH build that read every primitive of a node: binning its centroids ({@link #bin}) and
 * summarizing a range ({@link #summarize}), and the merge of two summaries. Two implementations give bit-identical
 * results (minima and maxima are exact, and each centroid is the same double sum): a scalar one, and one on the
 * JDK's incubating Vector API that handles a box's three minima, three maxima and its centroid's coordinates in three
 * vectors of four doubles. Chosen as {@link WideBoxTest} is, on first use ({@link #selected}): the vectorized one
 * where the JVM has the module and the CPU 256-bit vectors.
 *
 * <p>A primitive's box is {@link BVH#BOX_STRIDE} floats ({@link BVH#BOX_MAX} the offset of its maximum corner); a
 * summary is {@link SahSplitter#SUMMARY} doubles, its box and its centroids' box, each corner in four (the fourth
 * unused), so that a vector of four doubles reads or writes a corner.
 */
abstract class PrimitiveBinning {
    private static final PrimitiveBinning SCALAR = new ScalarPrimitiveBinning();

    /**
     * The binning this JVM runs: vectorized where it can be, scalar otherwise. Made on first use, by a holder class:
     * the vectorized class loads the Vector API, tens of milliseconds in a new JVM, which a tree of one primitive (a
     * scene whose only bounded shape is a sphere, say) never needs.
     */
    static PrimitiveBinning selected() {
        return Selected.BINNING;
    }

    private static final class Selected {
        static final PrimitiveBinning BINNING = select();
    }

    /** Primitives from which a range is binned by the scalar code until the vectorized code is {@link #warm}. */
    private static final int COLD_RANGE = 16;
    /** Calls of the vectorized code on smaller ranges after which it counts as compiled. */
    private static final int WARM_CALLS = 100_000;

    /** Calls of the vectorized code so far; racy on purpose, a lost increment only delays {@link #warm}. */
    private static int vectorCalls;

    private static boolean warm;

    /**
     * The binning for a range of {@code primitives}: {@link #selected}, except that a single primitive gets the scalar
     * code (nothing to gain, and a tree of one then never loads the vectorized class), and that until the vectorized
     * code has run {@link #WARM_CALLS} times on smaller ranges, large ranges get the scalar code. Before the JIT
     * compiles it, vector code runs as objects (each operation allocates) and is far slower than scalar code, and the
     * top of a fresh JVM's first build is binned before anything is compiled. The 1M heightfield's first build in a
     * fresh JVM, alternated with the build before the Vector API binning: with the vectorized code throughout 1.46 and
     * 1.50 times as long (pairwise medians of two runs, four and three pairs), so 1.11-1.17 times (four runs of six
     * pairs; the second build 0.75 times). Both give the same bins, so which runs changes no tree.
     */
    static PrimitiveBinning forRange(int primitives) {
        if (primitives < 2) return SCALAR;
        if (warm) return selected();
        if (primitives >= COLD_RANGE) return SCALAR;
        if (++vectorCalls >= WARM_CALLS) warm = true;
        return selected();
    }

    /**
     * The binning for {@link #bin binning} a range of {@code primitives} whose box is {@code summary[at..]}: as {@link
     * #forRange}, but the scalar code where the box spans some axis from -inf to +inf, whose primitives' centroids there
     * may be NaN (see {@link #bin}).
     */
    static PrimitiveBinning forBinning(int primitives, double[] summary, int at) {
        for (int a = 0; a < 3; a++) {
            if (summary[at + SahSplitter.MIN + a] == Double.NEGATIVE_INFINITY
                    && summary[at + SahSplitter.MAX + a] == Double.POSITIVE_INFINITY) {
                return SCALAR;
            }
        }
        return forRange(primitives);
    }

    /**
     * Adds each primitive of {@code index[start..end)} to the bin of its centroid on {@code axis}: its count, and its
     * box and centroid to the bin's summary, and records its bin at {@code binOfPosition[k - start]}. A bin's summary
     * is written by its first primitive; only bins listed in {@link SahBins#used} (in the order first used) hold
     * anything, and {@code bins} must be {@link SahBins#clear cleared} for at least {@code end - start} primitives.
     *
     * <p>The boxes must hold no -0.0 ({@link BVH#build(float[], int, int, boolean, boolean[])} sets such bounds to
     * 0.0), and, for the vectorized code, none may span an axis from -inf to +inf ({@link #forBinning} gives such
     * ranges the scalar code). Then no centroid is NaN or -0.0, and a minimum or maximum by one comparison and a blend,
     * as the vectorized code takes them, is {@link Math#min}'s or {@link Math#max}'s, which the scalar code takes.
     */
    abstract void bin(float[] boxes, int[] index, int start, int end, int axis, double lo, double scale, SahBins bins);

    /** Writes the summary of the primitives of {@code index[start..end)} to {@code out[at..at+SUMMARY)}. */
    abstract void summarize(float[] boxes, int[] index, int start, int end, double[] out, int at);

    /** Merges the summary at {@code from[f..]} into the one at {@code to[t..]}. */
    abstract void merge(double[] from, int f, double[] to, int t);

    /** A short name for reports and tests: "vector" or "scalar". */
    abstract String name();

    /**
     * The bin of a centroid: conversion truncates toward zero, what lies below {@code lo} goes to bin 0, what lies at
     * or beyond the last bin's end to the last, and NaN (infinite boxes) to bin 0.
     */
    static int binOf(double centroid, double lo, double scale, int bins) {
        int bin = (int) ((centroid - lo) * scale);
        return bin < 0 ? 0 : bin >= bins ? bins - 1 : bin;
    }

    private static PrimitiveBinning select() {
        return VectorKernels.select(
                PrimitiveBinning.class, "geometries.VectorPrimitiveBinning", ScalarPrimitiveBinning::new);
    }
}
