package geometries;

import java.util.Arrays;

/**
 * The binned surface-area heuristic that decides each node of a {@link BvhBuilder}'s tree: the centroids of a
 * node's primitives are binned along the axis of largest centroid extent, and the cheapest bin boundary is taken
 * unless a leaf is cheaper; the primitives are then partitioned, each side in its order, in the shared index.
 *
 * <p>A range of primitives is known by its summary: its primitives' box, then the box of their centroids
 * ({@link #SUMMARY} doubles). The bins of a split hold exactly its children's summaries, so a node needs no pass
 * of its own over its primitives; only the root is summarized by a pass. The passes over a node's primitives are
 * {@link PrimitiveBinning}'s. One splitter serves one thread.
 */
final class SahSplitter {
    /**
     * Doubles in a range's summary: its primitives' box, minimum then maximum corner, then their centroids' box; each
     * corner x, y, z and an unused fourth, so that a vector of four doubles reads or writes it.
     */
    static final int SUMMARY = 16;
    /** Offsets in a summary of the box's minimum and maximum corners, and of the centroids' box's. */
    static final int MIN = 0, MAX = 4, CENTROID_MIN = 8, CENTROID_MAX = 12;

    private final float[] boxes;
    private final int[] index;
    private final int maxLeafSize;
    /** The small groups made leaves whatever the SAH says. */
    private final FilledLeaves filled;
    /** The bins of the node being split. */
    private final SahBins bins;
    /** Per used bin, in order, the area of the union of it and the used bins after it. */
    private final double[] rightArea;
    /** Per depth, the summaries of the two children the split at that depth made: left, then right. */
    final double[] childSummaries = new double[2 * SUMMARY * (BVH.MAX_DEPTH + 1)];
    /** The axis of the last split. */
    int splitAxis;

    /**
     * A splitter over primitives given by their boxes ({@link BVH#BOX_STRIDE} floats each, {@link
     * PrimitiveCollector#boxes}) and reached through {@code index}, which it partitions.
     */
    SahSplitter(float[] boxes, int[] index, int bins, int maxLeafSize, FilledLeaves filled) {
        this.filled = filled;
        this.boxes = boxes;
        this.index = index;
        this.maxLeafSize = maxLeafSize;
        this.bins = new SahBins(bins);
        rightArea = new double[bins];
    }

    /** Where the summaries of the children of a split at {@code depth} lie in {@link #childSummaries}: left first. */
    static int childrenAt(int depth) {
        return 2 * SUMMARY * depth;
    }

    /** Writes the box of the summary at {@code summary[at..]}, rounded outward to floats, to {@code box[boxAt..]}. */
    static void roundedBox(double[] summary, int at, float[] box, int boxAt) {
        for (int a = 0; a < 3; a++) {
            box[boxAt + a] = FloatBoxes.floatBelow(summary[at + MIN + a]);
            box[boxAt + 3 + a] = FloatBoxes.floatAbove(summary[at + MAX + a]);
        }
    }

    /** Writes the summary of {@code [start, end)} to {@code out[at..at+SUMMARY)}: one pass over its primitives. */
    void summarize(int start, int end, double[] out, int at) {
        PrimitiveBinning.forRange(end - start).summarize(boxes, index, start, end, out, at);
    }

    /** An empty summary at {@code s[at..]}: each minimum corner +inf, each maximum corner -inf. */
    static void resetSummary(double[] s, int at) {
        Arrays.fill(s, at + MIN, at + MAX, Double.POSITIVE_INFINITY);
        Arrays.fill(s, at + MAX, at + CENTROID_MIN, Double.NEGATIVE_INFINITY);
        Arrays.fill(s, at + CENTROID_MIN, at + CENTROID_MAX, Double.POSITIVE_INFINITY);
        Arrays.fill(s, at + CENTROID_MAX, at + SUMMARY, Double.NEGATIVE_INFINITY);
    }

    /**
     * Decides the node over {@code [start, end)} at {@code depth}, summarized at {@code summary[at..]}: returns -1
     * for a leaf, or partitions the range and returns the split position, with the axis in {@link #splitAxis} and
     * the two children's summaries in {@link #childSummaries} at {@link #childrenAt childrenAt(depth)}.
     */
    int split(int start, int end, int depth, double[] summary, int at) {
        int count = end - start;
        if (count == 1 || depth >= BVH.MAX_DEPTH) return -1;
        int cMin = at + CENTROID_MIN, cMax = at + CENTROID_MAX;
        double ex = summary[cMax] - summary[cMin];
        double ey = summary[cMax + 1] - summary[cMin + 1];
        double ez = summary[cMax + 2] - summary[cMin + 2];
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        splitAxis = axis;
        double extent = axis == 0 ? ex : axis == 1 ? ey : ez;
        if (!(extent > 0)) {
            // All centroids coincide: nothing separates them, so split by count to keep leaves small.
            return count <= maxLeafSize ? -1 : halve(start, end, depth);
        }
        int min = at + MIN, max = at + MAX;
        double nodeArea = surfaceArea(
                summary[min], summary[min + 1], summary[min + 2], summary[max], summary[max + 1], summary[max + 2]);
        if (count <= maxLeafSize && (filled.fill(index, start, end) || leafIsCheaper(start, end, nodeArea, count))) {
            return -1;
        }
        return sahPartition(start, end, depth, summary, at, axis, nodeArea);
    }

    /**
     * Whether a leaf surely costs no more than any split of a node small enough to be one, known without binning it
     * (half the nodes of a mesh's tree are such leaves): each primitive's box lies in its child's, so a split costs at
     * least the traversal cost plus the sum of the primitives' areas over the node's. Rounding is monotone, so the
     * binned sweep's areas are at least these; the margin covers the rounding of the sum. The tree is the same.
     */
    private boolean leafIsCheaper(int start, int end, double nodeArea, int count) {
        if (!(nodeArea > 0)) return false;
        double sum = 0;
        for (int k = start; k < end; k++) {
            int o = BVH.BOX_STRIDE * index[k], m = o + BVH.BOX_MAX;
            sum += surfaceArea(boxes[o], boxes[o + 1], boxes[o + 2], boxes[m], boxes[m + 1], boxes[m + 2]);
        }
        return BVH.TRAVERSAL_COST + sum / nodeArea >= count * (1 + 1e-9);
    }

    /** Splits {@code [start, end)} by count where no bin boundary separates it; summarizes both halves. */
    private int halve(int start, int end, int depth) {
        int mid = start + (end - start) / 2;
        summarize(start, mid, childSummaries, childrenAt(depth));
        summarize(mid, end, childSummaries, childrenAt(depth) + SUMMARY);
        return mid;
    }

    /**
     * Partitions the node summarized at {@code summary[at..]} by the cheapest bin boundary on {@code axis} (its
     * centroids' extent there is positive); returns the split position, or -1 if a leaf is better.
     */
    private int sahPartition(int start, int end, int depth, double[] summary, int at, int axis, double nodeArea) {
        int count = end - start;
        double lo = summary[at + CENTROID_MIN + axis];
        double extent = summary[at + CENTROID_MAX + axis] - lo;
        // A bin's summary is written by its first primitive, and the sweeps visit only the bins used, in order: most
        // nodes are small, and resetting and sweeping sixteen bins cost more than binning their primitives.
        SahBins bins = this.bins;
        bins.clear(count);
        double scale = bins.size() / extent;
        PrimitiveBinning.forBinning(count, summary, at).bin(boxes, index, start, end, axis, lo, scale, bins);
        bins.sortUsed();
        int[] used = bins.used, binCount = bins.count;
        double[] binSummaries = bins.summaries;
        int n = bins.usedCount;
        // Sweep from the right: area of the union of the used bins from the u-th on.
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int u = n - 1; u > 0; u--) {
            int o = SUMMARY * used[u] + MIN, m = o - MIN + MAX;
            x0 = Math.min(x0, binSummaries[o]);
            y0 = Math.min(y0, binSummaries[o + 1]);
            z0 = Math.min(z0, binSummaries[o + 2]);
            x1 = Math.max(x1, binSummaries[m]);
            y1 = Math.max(y1, binSummaries[m + 1]);
            z1 = Math.max(z1, binSummaries[m + 2]);
            rightArea[u] = surfaceArea(x0, y0, z0, x1, y1, z1);
        }
        // Sweep from the left, pricing the split after each used bin but the last (after an empty bin, the split is
        // the one after the used bin before it).
        x0 = y0 = z0 = Double.POSITIVE_INFINITY;
        x1 = y1 = z1 = Double.NEGATIVE_INFINITY;
        int leftCount = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1, bestLeftCount = 0, bestUsed = 0;
        for (int u = 0; u < n - 1; u++) {
            int bin = used[u], o = SUMMARY * bin + MIN, m = o - MIN + MAX;
            x0 = Math.min(x0, binSummaries[o]);
            y0 = Math.min(y0, binSummaries[o + 1]);
            z0 = Math.min(z0, binSummaries[o + 2]);
            x1 = Math.max(x1, binSummaries[m]);
            y1 = Math.max(y1, binSummaries[m + 1]);
            z1 = Math.max(z1, binSummaries[m + 2]);
            leftCount += binCount[bin];
            int rightCount = count - leftCount;
            double cost = leftCount * surfaceArea(x0, y0, z0, x1, y1, z1) + rightCount * rightArea[u + 1];
            if (cost < bestCost) {
                bestCost = cost;
                bestSplit = bin;
                bestLeftCount = leftCount;
                bestUsed = u;
            }
        }
        double splitCost = BVH.TRAVERSAL_COST + (nodeArea > 0 ? bestCost / nodeArea : 0);
        if (bestSplit < 0) {
            return count <= maxLeafSize ? -1 : halve(start, end, depth);
        }
        if (count <= maxLeafSize && splitCost >= count) return -1;
        // The children's summaries are their bins' (the same primitives), then the partition: bins
        // [0, bestSplit] to the left.
        int left = childrenAt(depth), right = left + SUMMARY;
        // Each side starts as a copy of its first bin: cheaper than resetting it, on the many small nodes.
        System.arraycopy(binSummaries, SUMMARY * used[0], childSummaries, left, SUMMARY);
        PrimitiveBinning binning = PrimitiveBinning.selected();
        for (int u = 1; u <= bestUsed; u++) binning.merge(binSummaries, SUMMARY * used[u], childSummaries, left);
        System.arraycopy(binSummaries, SUMMARY * used[bestUsed + 1], childSummaries, right, SUMMARY);
        for (int u = bestUsed + 2; u < n; u++) binning.merge(binSummaries, SUMMARY * used[u], childSummaries, right);
        // Each primitive to the side of its bin (recorded at its position), both sides in the order they were: the left
        // ones moved down in place, the right ones through a scratch array. Branch-free, and no load waits on the
        // previous primitive's store, as in a partition by swaps; and the order kept keeps runs of neighbours in the
        // same bins for the children's binning.
        byte[] binOf = bins.binOfPosition;
        int[] rightSide = bins.rightSide;
        int i = start, r = 0;
        for (int k = start; k < end; k++) {
            int p = index[k];
            int goesLeft = (binOf[k - start] & 0xFF) <= bestSplit ? 1 : 0;
            index[i] = p;
            rightSide[r] = p;
            i += goesLeft;
            r += 1 - goesLeft;
        }
        System.arraycopy(rightSide, 0, index, i, r);
        // The children's boxes come from the bins, so a partition that disagreed with them would make boxes that miss
        // their primitives (and, with a side left empty, a tree that never ends): refuse rather than build it. The
        // sides follow the recorded bins, so only a binning that recorded other bins than it counted could trip this.
        if (i - start != bestLeftCount) {
            throw new IllegalStateException("BVH build: the partition put " + (i - start) + " primitives left of bin "
                    + bestSplit + ", its bins counted " + bestLeftCount);
        }
        return i;
    }

    /** The surface area of a box. */
    static double surfaceArea(double x0, double y0, double z0, double x1, double y1, double z1) {
        double ex = x1 - x0, ey = y1 - y0, ez = z1 - z0;
        return 2 * (ex * ey + ey * ez + ez * ex);
    }
}
