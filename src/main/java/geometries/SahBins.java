package geometries;

/**
 * The bins of one SAH split: per bin the primitives whose centroids fall in it and their summary, and which bins the
 * split used. Most nodes are small: a bin is written by its first primitive and read only if used, so that no split
 * resets or sweeps bins it never filled.
 */
final class SahBins {
    /** Primitives per bin. */
    final int[] count;
    /** Per bin, {@link SahSplitter#SUMMARY} doubles: the box and the centroids' box of its primitives. */
    final double[] summaries;
    /** The bins used, in the order first used (then sorted), and how many. */
    final int[] used;

    int usedCount;
    /**
     * The bin of each primitive binned last, by position in the range ({@code k - start}), so that the partition sends
     * each primitive to the side of the bin that counted it without computing its centroid again.
     */
    byte[] binOfPosition = new byte[0];
    /** Room for the primitives that the partition sends right, in their order, until it copies them back. */
    int[] rightSide = new int[0];

    SahBins(int bins) {
        if (bins > 256) throw new IllegalArgumentException("at most 256 bins: a bin is kept in a byte");
        count = new int[bins];
        summaries = new double[SahSplitter.SUMMARY * bins];
        used = new int[bins];
    }

    /** How many bins there are. */
    int size() {
        return count.length;
    }

    /** Empties the bins the last split used, and makes room for binning {@code primitives}. */
    void clear(int primitives) {
        if (binOfPosition.length < primitives) {
            binOfPosition = new byte[primitives];
            rightSide = new int[primitives];
        }
        for (int u = 0; u < usedCount; u++) count[used[u]] = 0;
        usedCount = 0;
    }

    /** Sorts the used bins in order along the axis (insertion sort: a handful of bins). */
    void sortUsed() {
        for (int u = 1; u < usedCount; u++) {
            int bin = used[u], v = u;
            for (; v > 0 && used[v - 1] > bin; v--) used[v] = used[v - 1];
            used[v] = bin;
        }
    }
}
