package geometries;

import java.util.Arrays;

/**
 * The binned surface-area heuristic that decides each node of a {@link BvhBuilder}'s tree: the centroids of a
 * node's primitives are binned along the axis of largest centroid extent, and the cheapest bin boundary is taken
 * unless a leaf is cheaper; the primitives are then partitioned in place in the shared index.
 *
 * <p>A range of primitives is known by its summary: its primitives' box, then the box of their centroids
 * ({@link #SUMMARY} doubles). The bins of a split hold exactly its children's summaries, so a node needs no pass
 * of its own over its primitives; only the root is summarized by a pass. One splitter serves one thread.
 */
final class SahSplitter {
    /** Doubles in a range's summary: its primitives' box (min x, y, z, max x, y, z), then their centroids' box. */
    static final int SUMMARY = 12;

    private final float[] primBounds;
    private final int[] index;
    private final int bins;
    private final int maxLeafSize;
    private final int[] binCount;
    /** Per bin, the summary of the primitives whose centroids fall in it. */
    private final double[] binSummaries;

    /** The bins the node being split uses, in the order first used (then sorted), and how many. */
    private final int[] used;

    private int usedCount;
    /** Per used bin, in order, the area of the union of it and the used bins after it. */
    private final double[] rightArea;
    /** Per depth, the summaries of the two children the split at that depth made: left, then right. */
    final double[] childSummaries = new double[2 * SUMMARY * (BVH.MAX_DEPTH + 1)];
    /** The axis of the last split. */
    int splitAxis;

    /**
     * A splitter over primitives given by their boxes (six floats each, {@link PrimitiveCollector#boxes}) and
     * reached through {@code index}, which it partitions.
     */
    SahSplitter(float[] primBounds, int[] index, int bins, int maxLeafSize) {
        this.primBounds = primBounds;
        this.index = index;
        this.bins = bins;
        this.maxLeafSize = maxLeafSize;
        binCount = new int[bins];
        binSummaries = new double[SUMMARY * bins];
        used = new int[bins];
        rightArea = new double[bins];
    }

    /** Where the summaries of the children of a split at {@code depth} lie in {@link #childSummaries}: left first. */
    static int childrenAt(int depth) {
        return 2 * SUMMARY * depth;
    }

    /** Writes the box of the summary at {@code summary[at..]}, rounded outward to floats, to {@code box[boxAt..]}. */
    static void roundedBox(double[] summary, int at, float[] box, int boxAt) {
        for (int a = 0; a < 3; a++) {
            box[boxAt + a] = BVH.floatBelow(summary[at + a]);
            box[boxAt + 3 + a] = BVH.floatAbove(summary[at + 3 + a]);
        }
    }

    /**
     * Centroid of primitive {@code p} on {@code axis}, computed where needed rather than stored: the box it
     * comes from is read anyway, and a stored copy cost another cache miss per primitive and pass. The sum is taken
     * in double, as the binning takes it: in float it would round differently, and a primitive binned on one side
     * could be partitioned to the other.
     */
    private double centroid(int p, int axis) {
        return 0.5 * ((double) primBounds[6 * p + axis] + primBounds[6 * p + 3 + axis]);
    }

    /** Writes the summary of {@code [start, end)} to {@code out[at..at+SUMMARY)}: one pass over its primitives. */
    void summarize(int start, int end, double[] out, int at) {
        resetSummary(out, at);
        for (int k = start; k < end; k++) include(index[k], out, at);
    }

    private static void resetSummary(double[] s, int at) {
        Arrays.fill(s, at, at + 3, Double.POSITIVE_INFINITY);
        Arrays.fill(s, at + 3, at + 6, Double.NEGATIVE_INFINITY);
        Arrays.fill(s, at + 6, at + 9, Double.POSITIVE_INFINITY);
        Arrays.fill(s, at + 9, at + 12, Double.NEGATIVE_INFINITY);
    }

    /** Adds primitive {@code p}'s box and centroid to the summary at {@code s[at..]}. */
    private void include(int p, double[] s, int at) {
        int o = 6 * p;
        double x0 = primBounds[o], y0 = primBounds[o + 1], z0 = primBounds[o + 2];
        double x1 = primBounds[o + 3], y1 = primBounds[o + 4], z1 = primBounds[o + 5];
        s[at] = Math.min(s[at], x0);
        s[at + 1] = Math.min(s[at + 1], y0);
        s[at + 2] = Math.min(s[at + 2], z0);
        s[at + 3] = Math.max(s[at + 3], x1);
        s[at + 4] = Math.max(s[at + 4], y1);
        s[at + 5] = Math.max(s[at + 5], z1);
        double x = 0.5 * (x0 + x1), y = 0.5 * (y0 + y1), z = 0.5 * (z0 + z1);
        s[at + 6] = Math.min(s[at + 6], x);
        s[at + 7] = Math.min(s[at + 7], y);
        s[at + 8] = Math.min(s[at + 8], z);
        s[at + 9] = Math.max(s[at + 9], x);
        s[at + 10] = Math.max(s[at + 10], y);
        s[at + 11] = Math.max(s[at + 11], z);
    }

    /**
     * Adds a run of {@code run} primitives, summarized by the twelve values (box, then centroids' box), to {@code bin}:
     * the first run of a bin writes its summary, later ones merge (min and max are exact in any order).
     */
    private void addRun(
            int bin,
            int run,
            double x0,
            double y0,
            double z0,
            double x1,
            double y1,
            double z1,
            double cx0,
            double cy0,
            double cz0,
            double cx1,
            double cy1,
            double cz1) {
        double[] s = binSummaries;
        int o = SUMMARY * bin;
        if (binCount[bin] == 0) {
            used[usedCount++] = bin;
            s[o] = x0;
            s[o + 1] = y0;
            s[o + 2] = z0;
            s[o + 3] = x1;
            s[o + 4] = y1;
            s[o + 5] = z1;
            s[o + 6] = cx0;
            s[o + 7] = cy0;
            s[o + 8] = cz0;
            s[o + 9] = cx1;
            s[o + 10] = cy1;
            s[o + 11] = cz1;
        } else {
            // Written out, like include's: one helper for both put the sequential 1M build at 0.487-0.492 s against
            // 0.427-0.429 s (best of 15, three alternated pairs), the JIT inlining this path differently.
            s[o] = Math.min(s[o], x0);
            s[o + 1] = Math.min(s[o + 1], y0);
            s[o + 2] = Math.min(s[o + 2], z0);
            s[o + 3] = Math.max(s[o + 3], x1);
            s[o + 4] = Math.max(s[o + 4], y1);
            s[o + 5] = Math.max(s[o + 5], z1);
            s[o + 6] = Math.min(s[o + 6], cx0);
            s[o + 7] = Math.min(s[o + 7], cy0);
            s[o + 8] = Math.min(s[o + 8], cz0);
            s[o + 9] = Math.max(s[o + 9], cx1);
            s[o + 10] = Math.max(s[o + 10], cy1);
            s[o + 11] = Math.max(s[o + 11], cz1);
        }
        binCount[bin] += run;
    }

    /** Merges the summary at {@code from[f..]} into the one at {@code to[t..]}. */
    private static void merge(double[] from, int f, double[] to, int t) {
        for (int i = 0; i < 3; i++) {
            to[t + i] = Math.min(to[t + i], from[f + i]);
            to[t + 3 + i] = Math.max(to[t + 3 + i], from[f + 3 + i]);
            to[t + 6 + i] = Math.min(to[t + 6 + i], from[f + 6 + i]);
            to[t + 9 + i] = Math.max(to[t + 9 + i], from[f + 9 + i]);
        }
    }

    /**
     * Decides the node over {@code [start, end)} at {@code depth}, summarized at {@code summary[at..]}: returns -1
     * for a leaf, or partitions the range and returns the split position, with the axis in {@link #splitAxis} and
     * the two children's summaries in {@link #childSummaries} at {@link #childrenAt childrenAt(depth)}.
     */
    int split(int start, int end, int depth, double[] summary, int at) {
        int count = end - start;
        if (count == 1 || depth >= BVH.MAX_DEPTH) return -1;
        double ex = summary[at + 9] - summary[at + 6];
        double ey = summary[at + 10] - summary[at + 7];
        double ez = summary[at + 11] - summary[at + 8];
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        splitAxis = axis;
        double lo = summary[at + 6 + axis];
        double extent = axis == 0 ? ex : axis == 1 ? ey : ez;
        if (!(extent > 0)) {
            // All centroids coincide: nothing separates them, so split by count to keep leaves small.
            return count <= maxLeafSize ? -1 : halve(start, end, depth);
        }
        double nodeArea = surfaceArea(
                summary[at], summary[at + 1], summary[at + 2], summary[at + 3], summary[at + 4], summary[at + 5]);
        if (count <= maxLeafSize && leafIsCheaper(start, end, nodeArea, count)) return -1;
        return sahPartition(start, end, depth, axis, lo, extent, nodeArea, count);
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
            int o = 6 * index[k];
            sum += surfaceArea(
                    primBounds[o],
                    primBounds[o + 1],
                    primBounds[o + 2],
                    primBounds[o + 3],
                    primBounds[o + 4],
                    primBounds[o + 5]);
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

    /** Partitions by the cheapest bin boundary; returns the split position, or -1 if a leaf is better. */
    private int sahPartition(
            int start, int end, int depth, int axis, double lo, double extent, double nodeArea, int count) {
        // A bin's summary is written by its first primitive, and the sweeps visit only the bins used, in order: most
        // nodes are small, and resetting and sweeping sixteen bins cost more than binning their primitives.
        for (int u = 0; u < usedCount; u++) binCount[used[u]] = 0;
        usedCount = 0;
        double scale = bins / extent;
        // Neighbours in the index mostly fall in the same bin: a run of them is summarized in locals and merged
        // into its bin once, not primitive by primitive through memory (each merge waiting for the last one's store).
        int runBin = -1, run = 0;
        double rx0 = 0, ry0 = 0, rz0 = 0, rx1 = 0, ry1 = 0, rz1 = 0;
        double rcx0 = 0, rcy0 = 0, rcz0 = 0, rcx1 = 0, rcy1 = 0, rcz1 = 0;
        for (int k = start; k < end; k++) {
            int o = 6 * index[k];
            double x0 = primBounds[o], y0 = primBounds[o + 1], z0 = primBounds[o + 2];
            double x1 = primBounds[o + 3], y1 = primBounds[o + 4], z1 = primBounds[o + 5];
            double x = 0.5 * (x0 + x1), y = 0.5 * (y0 + y1), z = 0.5 * (z0 + z1);
            int bin = binOf(axis == 0 ? x : axis == 1 ? y : z, lo, scale);
            if (bin == runBin) {
                run++;
                rx0 = Math.min(rx0, x0);
                ry0 = Math.min(ry0, y0);
                rz0 = Math.min(rz0, z0);
                rx1 = Math.max(rx1, x1);
                ry1 = Math.max(ry1, y1);
                rz1 = Math.max(rz1, z1);
                rcx0 = Math.min(rcx0, x);
                rcy0 = Math.min(rcy0, y);
                rcz0 = Math.min(rcz0, z);
                rcx1 = Math.max(rcx1, x);
                rcy1 = Math.max(rcy1, y);
                rcz1 = Math.max(rcz1, z);
                continue;
            }
            if (run > 0) addRun(runBin, run, rx0, ry0, rz0, rx1, ry1, rz1, rcx0, rcy0, rcz0, rcx1, rcy1, rcz1);
            runBin = bin;
            run = 1;
            rx0 = x0;
            ry0 = y0;
            rz0 = z0;
            rx1 = x1;
            ry1 = y1;
            rz1 = z1;
            rcx0 = rcx1 = x;
            rcy0 = rcy1 = y;
            rcz0 = rcz1 = z;
        }
        if (run > 0) addRun(runBin, run, rx0, ry0, rz0, rx1, ry1, rz1, rcx0, rcy0, rcz0, rcx1, rcy1, rcz1);
        int[] used = this.used;
        int n = usedCount;
        for (int u = 1; u < n; u++) { // insertion sort: a handful of bins
            int bin = used[u], v = u;
            for (; v > 0 && used[v - 1] > bin; v--) used[v] = used[v - 1];
            used[v] = bin;
        }
        // Sweep from the right: area of the union of the used bins from the u-th on.
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int u = n - 1; u > 0; u--) {
            int o = SUMMARY * used[u];
            x0 = Math.min(x0, binSummaries[o]);
            y0 = Math.min(y0, binSummaries[o + 1]);
            z0 = Math.min(z0, binSummaries[o + 2]);
            x1 = Math.max(x1, binSummaries[o + 3]);
            y1 = Math.max(y1, binSummaries[o + 4]);
            z1 = Math.max(z1, binSummaries[o + 5]);
            rightArea[u] = surfaceArea(x0, y0, z0, x1, y1, z1);
        }
        // Sweep from the left, pricing the split after each used bin but the last (after an empty bin, the split is
        // the one after the used bin before it).
        x0 = y0 = z0 = Double.POSITIVE_INFINITY;
        x1 = y1 = z1 = Double.NEGATIVE_INFINITY;
        int leftCount = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1, bestLeftCount = 0;
        for (int u = 0; u < n - 1; u++) {
            int bin = used[u], o = SUMMARY * bin;
            x0 = Math.min(x0, binSummaries[o]);
            y0 = Math.min(y0, binSummaries[o + 1]);
            z0 = Math.min(z0, binSummaries[o + 2]);
            x1 = Math.max(x1, binSummaries[o + 3]);
            y1 = Math.max(y1, binSummaries[o + 4]);
            z1 = Math.max(z1, binSummaries[o + 5]);
            leftCount += binCount[bin];
            int rightCount = count - leftCount;
            double cost = leftCount * surfaceArea(x0, y0, z0, x1, y1, z1) + rightCount * rightArea[u + 1];
            if (cost < bestCost) {
                bestCost = cost;
                bestSplit = bin;
                bestLeftCount = leftCount;
            }
        }
        double splitCost = BVH.TRAVERSAL_COST + (nodeArea > 0 ? bestCost / nodeArea : 0);
        if (bestSplit < 0) {
            return count <= maxLeafSize ? -1 : halve(start, end, depth);
        }
        if (count <= maxLeafSize && splitCost >= count) return -1;
        // The children's summaries are their bins' (the same primitives), then partition in place: bins
        // [0, bestSplit] to the left.
        int left = childrenAt(depth), right = left + SUMMARY;
        resetSummary(childSummaries, left);
        resetSummary(childSummaries, right);
        for (int u = 0; u < n; u++) {
            merge(binSummaries, SUMMARY * used[u], childSummaries, used[u] <= bestSplit ? left : right);
        }
        // binOf gives at most bestSplit exactly where (c - lo) * scale is not at least bestSplit + 1: conversion
        // truncates toward zero, the clamps send what lies below 0 to bin 0 and what lies from bins on to the last bin
        // (never left of a split), and NaN (infinite boxes) converts to bin 0. The same sides, without the conversion.
        double leftLimit = bestSplit + 1;
        int i = start;
        for (int k = start; k < end; k++) {
            int p = index[k];
            int goesLeft = (centroid(p, axis) - lo) * scale >= leftLimit ? 0 : 1;
            index[k] = index[i];
            index[i] = p;
            i += goesLeft;
        }
        // The children's boxes come from the bins, so a partition that disagreed with them would make boxes that miss
        // their primitives (and, with a side left empty, a tree that never ends): refuse rather than build it.
        if (i - start != bestLeftCount) {
            throw new IllegalStateException("BVH build: the partition put " + (i - start) + " primitives left of bin "
                    + bestSplit + ", its bins counted " + bestLeftCount);
        }
        return i;
    }

    private int binOf(double centroid, double lo, double scale) {
        int bin = (int) ((centroid - lo) * scale);
        return bin < 0 ? 0 : bin >= bins ? bins - 1 : bin;
    }

    /** The surface area of a box. */
    static double surfaceArea(double x0, double y0, double z0, double x1, double y1, double z1) {
        double ex = x1 - x0, ey = y1 - y0, ez = z1 - z0;
        return 2 * (ex * ey + ey * ez + ez * ex);
    }
}
