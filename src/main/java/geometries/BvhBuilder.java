package geometries;

import java.util.Arrays;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.ForkJoinWorkerThread;

/**
 * The binned-SAH build of a {@link BVH}'s binary tree: at each node the centroids are binned along the axis of
 * largest centroid extent and the cheapest bin boundary is taken unless a leaf is cheaper; nodes are written
 * depth-first into arrays sized once for the 2n - 1 nodes a binary tree can have. Large inputs build their
 * subtrees in parallel, into the very tree the sequential build gives. {@link BVH} then collapses it into wide
 * nodes.
 */
final class BvhBuilder {
    /**
     * Doubles in a range's summary: its primitives' box (min x, y, z, max x, y, z), then the box of their centroids.
     * A split's bins already hold its children's summaries, so a node needs no pass of its own over its primitives.
     */
    private static final int SUMMARY = 12;

    private final double[] primBounds;
    final int[] index;
    private final int bins;
    private final int maxLeafSize;
    private final int[] binCount;
    /** Per bin, the summary of the primitives whose centroids fall in it. */
    private final double[] binSummaries;

    private final double[] rightArea;
    /** Per depth, the summaries of the two children the split at that depth made: left, then right. */
    private final double[] childSummaries = new double[2 * SUMMARY * (BVH.MAX_DEPTH + 1)];
    /** Scratch for the split axis {@link #split} reports. */
    private final int[] axis = new int[1];

    /**
     * Six floats per node, its box rounded outward ({@link BVH#floatBelow}, {@link BVH#floatAbove}): all the collapse
     * and the traversal need, at half the memory of doubles.
     */
    float[] bounds;

    int[] data;
    int nodeCount;
    int leafCount;
    int maxDepthReached;

    /**
     * Whether the root divides the primitives into the two groups of {@link #BvhBuilder(double[], int, int, boolean,
     * boolean[])}: its first child holds the first group, its second child the second.
     */
    boolean grouped;

    /**
     * Builds the tree; with {@code secondGroup} naming some but not all primitives, the root's two children are
     * the trees of the other primitives and of those (each built as usual), so a query that needs only the first
     * group can leave the second's subtree out.
     */
    BvhBuilder(double[] primBounds, int bins, int maxLeafSize, boolean parallel, boolean[] secondGroup) {
        this(primBounds, grouped(primBounds.length / 6, secondGroup), bins, maxLeafSize);
        int n = index.length;
        int split = firstOfSecondGroup(n, secondGroup);
        grouped = split > 0;
        if (grouped) {
            // The forced root over the two groups' trees, laid out as the parallel build lays out its top.
            double[] groups = new double[2 * SUMMARY];
            summarize(0, split, groups, 0);
            summarize(split, n, groups, SUMMARY);
            Object top;
            if (parallel) {
                top = pool().invoke(ForkJoinTask.adapt(() -> {
                    ForkJoinTask<Object> left = ForkJoinTask.adapt(() -> plan(0, split, 1, groups, 0))
                            .fork();
                    Object right = plan(split, n, 1, groups, SUMMARY);
                    return groupRoot(left.join(), right);
                }));
            } else {
                top = groupRoot(subtree(0, split, 1, groups, 0), subtree(split, n, 1, groups, SUMMARY));
            }
            emitAll(top);
        } else if (n > 0) {
            double[] root = new double[SUMMARY];
            summarize(0, n, root, 0);
            if (parallel && n >= 2 * BVH.PARALLEL_GRAIN) {
                emitAll(pool().invoke(ForkJoinTask.adapt(() -> plan(0, n, 0, root, 0))));
            } else {
                allocate(2 * n - 1);
                build(0, n, 0, root, 0);
            }
        } else {
            allocate(1);
        }
    }

    /** The root over the two groups' planned trees: its box is the union of theirs. */
    private static Split groupRoot(Object left, Object right) {
        float[] box = boxOf(left).clone(), other = boxOf(right);
        // Minima and maxima of boxes already rounded outward: the box of the union, rounded outward.
        for (int a = 0; a < 3; a++) {
            box[a] = Math.min(box[a], other[a]);
            box[3 + a] = Math.max(box[3 + a], other[3 + a]);
        }
        return new Split(box, 0, left, right);
    }

    /** The build's own fork/join pool, one worker per core: the common pool leaves a core to a caller that waits. */
    private static ForkJoinPool pool;

    private static synchronized ForkJoinPool pool() {
        if (pool == null) pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
        return pool;
    }

    /**
     * The primitives in order, those of the second group last (each group in its own order), when neither group is
     * empty; otherwise in order.
     */
    private static int[] grouped(int n, boolean[] secondGroup) {
        if (firstOfSecondGroup(n, secondGroup) < 0) return identity(n);
        int[] index = new int[n];
        int k = 0;
        for (int i = 0; i < n; i++) if (!secondGroup[i]) index[k++] = i;
        for (int i = 0; i < n; i++) if (secondGroup[i]) index[k++] = i;
        return index;
    }

    /** The second group's first position in {@link #grouped} order, or -1 without groups or if one is empty. */
    private static int firstOfSecondGroup(int n, boolean[] secondGroup) {
        if (secondGroup == null) return -1;
        int first = 0;
        for (int i = 0; i < n; i++) if (!secondGroup[i]) first++;
        return first > 0 && first < n ? first : -1;
    }

    /** The rounded box of a planned node: a split's own, or a built subtree's root's. */
    private static float[] boxOf(Object planned) {
        if (planned instanceof Split split) return split.box();
        return Arrays.copyOf(((Subtree) planned).bounds(), 6);
    }

    /** A builder over a shared {@code index}; {@link #allocate} gives it room for nodes. */
    private BvhBuilder(double[] primBounds, int[] index, int bins, int maxLeafSize) {
        this.primBounds = primBounds;
        this.index = index;
        this.bins = bins;
        this.maxLeafSize = maxLeafSize;
        binCount = new int[bins];
        binSummaries = new double[SUMMARY * bins];
        rightArea = new double[bins];
    }

    /**
     * Allocates room for {@code nodes} nodes, at least one. A binary tree over n primitives has at most 2n - 1 nodes
     * (leaves hold at least one), so a sequential build allocates once: growing by doubling allocated and copied
     * twice the memory on large meshes.
     */
    private void allocate(int nodes) {
        bounds = new float[6 * Math.max(1, nodes)];
        data = new int[2 * Math.max(1, nodes)];
    }

    private static int[] identity(int n) {
        int[] index = new int[n];
        for (int i = 0; i < n; i++) index[i] = i;
        return index;
    }

    /** A subtree built by a builder of its own, its arrays trimmed to its nodes, ready for {@link #emit}. */
    private record Subtree(float[] bounds, int[] data, int nodeCount, int leafCount, int maxDepth) {}

    /** Room for the nodes of one parallel-build subtree. */
    private record Room(float[] bounds, int[] data) {
        Room() {
            this(new float[6 * (2 * BVH.PARALLEL_GRAIN - 1)], new int[2 * (2 * BVH.PARALLEL_GRAIN - 1)]);
        }
    }

    /**
     * Each worker of {@link #pool} builds its subtrees in the same room and copies each out at its final size,
     * instead of allocating every subtree the 2n - 1 nodes it might need.
     */
    private static final ThreadLocal<Room> ROOM = ThreadLocal.withInitial(Room::new);

    /** Builds {@code [start, end)} (summarized at {@code summary[at..]}) by a builder of its own. */
    private Subtree subtree(int start, int end, int depth, double[] summary, int at) {
        BvhBuilder builder = new BvhBuilder(primBounds, index, bins, maxLeafSize);
        if (end - start <= BVH.PARALLEL_GRAIN
                && Thread.currentThread() instanceof ForkJoinWorkerThread worker
                && worker.getPool() == pool) {
            Room room = ROOM.get();
            builder.bounds = room.bounds();
            builder.data = room.data();
        } else {
            builder.allocate(2 * (end - start) - 1);
        }
        builder.build(start, end, depth, summary, at);
        int nodes = builder.nodeCount;
        return new Subtree(
                Arrays.copyOf(builder.bounds, 6 * nodes),
                Arrays.copyOf(builder.data, 2 * nodes),
                nodes,
                builder.leafCount,
                builder.maxDepthReached);
    }

    /** An interior node of the top of the tree: its rounded box, split axis and two children. */
    private record Split(float[] box, int axis, Object left, Object right) {}

    /**
     * The parallel build, run in {@link #pool}: splits {@code [start, end)} exactly as {@link #build} would, builds
     * the left side in a forked task and the right here, down to ranges of at most {@link BVH#PARALLEL_GRAIN}
     * primitives, which builders of their own build (the ranges are disjoint parts of the shared index). Returns a
     * Split or a Subtree; {@link #emit} lays them out depth-first as the sequential build numbers its nodes, so the
     * tree is identical, bit for bit, to the sequential one whatever the number of cores.
     */
    private Object plan(int start, int end, int depth, double[] summary, int at) {
        if (end - start <= BVH.PARALLEL_GRAIN) return subtree(start, end, depth, summary, at);
        BvhBuilder top = new BvhBuilder(primBounds, index, bins, maxLeafSize);
        float[] box = new float[6];
        int mid = top.split(start, end, depth, summary, at, box, 0);
        if (mid < 0) return subtree(start, end, depth, summary, at);
        int axis = top.axis[0];
        double[] children = Arrays.copyOfRange(top.childSummaries, 2 * SUMMARY * depth, 2 * SUMMARY * (depth + 1));
        ForkJoinTask<Object> left = ForkJoinTask.adapt(() -> plan(start, mid, depth + 1, children, 0))
                .fork();
        Object right = plan(mid, end, depth + 1, children, SUMMARY);
        return new Split(box, axis, left.join(), right);
    }

    /** Allocates this builder's arrays at the size of the planned tree, then lays it out from node 0. */
    private void emitAll(Object planned) {
        allocate(nodesOf(planned));
        emit(planned);
    }

    private static int nodesOf(Object planned) {
        if (planned instanceof Subtree subtree) return subtree.nodeCount();
        Split split = (Split) planned;
        return 1 + nodesOf(split.left()) + nodesOf(split.right());
    }

    /** Lays out a planned node and everything below it at the next node index, depth-first. */
    private void emit(Object planned) {
        if (planned instanceof Subtree b) {
            int offset = nodeCount;
            System.arraycopy(b.bounds(), 0, bounds, 6 * offset, 6 * b.nodeCount());
            for (int i = 0; i < b.nodeCount(); i++) {
                int link = b.data()[2 * i], kind = b.data()[2 * i + 1];
                // Interior nodes link to their second child by node index; leaves to primitive positions.
                data[2 * (offset + i)] = kind < 0 ? link + offset : link;
                data[2 * (offset + i) + 1] = kind;
            }
            nodeCount += b.nodeCount();
            leafCount += b.leafCount();
            maxDepthReached = Math.max(maxDepthReached, b.maxDepth());
            return;
        }
        Split split = (Split) planned;
        int node = allocateNode();
        System.arraycopy(split.box(), 0, bounds, 6 * node, 6);
        emit(split.left());
        data[2 * node] = nodeCount;
        data[2 * node + 1] = -1 - split.axis();
        emit(split.right());
    }

    /** Primitives under each binary node, filled on first use by {@link #primitivesBelow}. */
    private int[] below;

    /**
     * The number of primitives in binary node {@code node}'s subtree.
     *
     * @param node a node of the finished tree
     * @return its primitive count
     */
    int primitivesBelow(int node) {
        if (below == null) {
            // Children follow their parents in depth-first order: one backward sweep sums every subtree.
            below = new int[nodeCount];
            for (int i = nodeCount - 1; i >= 0; i--) {
                int count = data[2 * i + 1];
                below[i] = count > 0 ? count : below[i + 1] + below[data[2 * i]];
            }
        }
        return below[node];
    }

    private int allocateNode() {
        return nodeCount++;
    }

    /**
     * Centroid of primitive {@code p} on {@code axis}, computed where needed rather than stored: the box it
     * comes from is read anyway, and a stored copy cost another cache miss per primitive and pass.
     */
    private double centroid(int p, int axis) {
        return 0.5 * (primBounds[6 * p + axis] + primBounds[6 * p + 3 + axis]);
    }

    /** Builds the subtree over {@code [start, end)}, summarized at {@code summary[at..]}, at the next node index. */
    private void build(int start, int end, int depth, double[] summary, int at) {
        int node = allocateNode();
        int mid = split(start, end, depth, summary, at, bounds, 6 * node);
        if (mid < 0) {
            makeLeaf(node, start, end - start);
            return;
        }
        int splitAxis = axis[0];
        int children = 2 * SUMMARY * depth;
        build(start, mid, depth + 1, childSummaries, children);
        int second = nodeCount;
        build(mid, end, depth + 1, childSummaries, children + SUMMARY);
        data[2 * node] = second;
        data[2 * node + 1] = -1 - splitAxis;
    }

    /** Writes the summary of {@code [start, end)} to {@code out[at..at+SUMMARY)}: one pass over its primitives. */
    private void summarize(int start, int end, double[] out, int at) {
        resetSummary(out, at);
        for (int k = start; k < end; k++) include(index[k], out, at);
    }

    private static void resetSummary(double[] s, int at) {
        Arrays.fill(s, at, at + 3, Double.POSITIVE_INFINITY);
        Arrays.fill(s, at + 3, at + 6, Double.NEGATIVE_INFINITY);
        Arrays.fill(s, at + 6, at + 9, Double.POSITIVE_INFINITY);
        Arrays.fill(s, at + 9, at + 12, Double.NEGATIVE_INFINITY);
    }

    /** Writes the summary of primitive {@code p} alone to {@code s[at..]}. */
    private void start(int p, double[] s, int at) {
        int o = 6 * p;
        for (int a = 0; a < 3; a++) {
            double min = primBounds[o + a], max = primBounds[o + 3 + a];
            s[at + a] = min;
            s[at + 3 + a] = max;
            s[at + 6 + a] = s[at + 9 + a] = 0.5 * (min + max);
        }
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
     * Decides the node over {@code [start, end)}, summarized at {@code summary[at..]}: writes its box rounded
     * outward to {@code box[boxAt..boxAt+6)}, and either returns -1 for a leaf or partitions the range and returns
     * the split position, with the split axis in {@link #axis} and the two children's summaries in
     * {@link #childSummaries} at this depth.
     */
    private int split(int start, int end, int depth, double[] summary, int at, float[] box, int boxAt) {
        int count = end - start;
        for (int a = 0; a < 3; a++) {
            box[boxAt + a] = BVH.floatBelow(summary[at + a]);
            box[boxAt + 3 + a] = BVH.floatAbove(summary[at + 3 + a]);
        }
        maxDepthReached = Math.max(maxDepthReached, depth);

        if (count == 1 || depth >= BVH.MAX_DEPTH) return -1;
        double ex = summary[at + 9] - summary[at + 6];
        double ey = summary[at + 10] - summary[at + 7];
        double ez = summary[at + 11] - summary[at + 8];
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        this.axis[0] = axis;
        double lo = summary[at + 6 + axis];
        double extent = axis == 0 ? ex : axis == 1 ? ey : ez;
        if (!(extent > 0)) {
            // All centroids coincide: nothing separates them, so split by count to keep leaves small.
            return count <= maxLeafSize ? -1 : halve(start, end, depth);
        }
        double nodeArea = surfaceArea(
                summary[at], summary[at + 1], summary[at + 2], summary[at + 3], summary[at + 4], summary[at + 5]);
        return sahPartition(start, end, depth, axis, lo, extent, nodeArea, count);
    }

    /** Splits {@code [start, end)} by count where no bin boundary separates it; summarizes both halves. */
    private int halve(int start, int end, int depth) {
        int mid = start + (end - start) / 2;
        summarize(start, mid, childSummaries, 2 * SUMMARY * depth);
        summarize(mid, end, childSummaries, 2 * SUMMARY * depth + SUMMARY);
        return mid;
    }

    /** Partitions by the cheapest bin boundary; returns the split position, or -1 if a leaf is better. */
    private int sahPartition(
            int start, int end, int depth, int axis, double lo, double extent, double nodeArea, int count) {
        // A bin's summary is written by its first primitive and only read where its count is positive, so no bin
        // is reset: most nodes are small, and resetting sixteen bins cost more than binning their primitives.
        Arrays.fill(binCount, 0);
        double scale = bins / extent;
        for (int k = start; k < end; k++) {
            int p = index[k];
            int bin = binOf(centroid(p, axis), lo, scale);
            if (binCount[bin]++ == 0) {
                start(p, binSummaries, SUMMARY * bin);
            } else {
                include(p, binSummaries, SUMMARY * bin);
            }
        }
        // Sweep from the right: area of the union of bins [i, bins).
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = bins - 1; i > 0; i--) {
            int o = SUMMARY * i;
            if (binCount[i] == 0) {
                rightArea[i] = i + 1 < bins ? rightArea[i + 1] : 0;
                continue;
            }
            x0 = Math.min(x0, binSummaries[o]);
            y0 = Math.min(y0, binSummaries[o + 1]);
            z0 = Math.min(z0, binSummaries[o + 2]);
            x1 = Math.max(x1, binSummaries[o + 3]);
            y1 = Math.max(y1, binSummaries[o + 4]);
            z1 = Math.max(z1, binSummaries[o + 5]);
            rightArea[i] = surfaceArea(x0, y0, z0, x1, y1, z1);
        }
        // Sweep from the left, pricing the split after bin i.
        x0 = y0 = z0 = Double.POSITIVE_INFINITY;
        x1 = y1 = z1 = Double.NEGATIVE_INFINITY;
        int leftCount = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1;
        for (int i = 0; i < bins - 1; i++) {
            int o = SUMMARY * i;
            if (binCount[i] == 0) continue; // the same split as after the last non-empty bin, which was priced
            x0 = Math.min(x0, binSummaries[o]);
            y0 = Math.min(y0, binSummaries[o + 1]);
            z0 = Math.min(z0, binSummaries[o + 2]);
            x1 = Math.max(x1, binSummaries[o + 3]);
            y1 = Math.max(y1, binSummaries[o + 4]);
            z1 = Math.max(z1, binSummaries[o + 5]);
            leftCount += binCount[i];
            int rightCount = count - leftCount;
            if (leftCount == 0 || rightCount == 0) continue;
            double cost = leftCount * surfaceArea(x0, y0, z0, x1, y1, z1) + rightCount * rightArea[i + 1];
            if (cost < bestCost) {
                bestCost = cost;
                bestSplit = i;
            }
        }
        double splitCost = BVH.TRAVERSAL_COST + (nodeArea > 0 ? bestCost / nodeArea : 0);
        if (bestSplit < 0) {
            return count <= maxLeafSize ? -1 : halve(start, end, depth);
        }
        if (count <= maxLeafSize && splitCost >= count) return -1;
        // The children's summaries are their bins' (the same primitives), then partition in place: bins
        // [0, bestSplit] to the left.
        int left = 2 * SUMMARY * depth, right = left + SUMMARY;
        resetSummary(childSummaries, left);
        resetSummary(childSummaries, right);
        for (int i = 0; i < bins; i++) {
            if (binCount[i] > 0) merge(binSummaries, SUMMARY * i, childSummaries, i <= bestSplit ? left : right);
        }
        int i = start, j = end - 1;
        while (i <= j) {
            if (binOf(centroid(index[i], axis), lo, scale) <= bestSplit) {
                i++;
            } else {
                int s = index[i];
                index[i] = index[j];
                index[j] = s;
                j--;
            }
        }
        return i;
    }

    private int binOf(double centroid, double lo, double scale) {
        int bin = (int) ((centroid - lo) * scale);
        return bin < 0 ? 0 : bin >= bins ? bins - 1 : bin;
    }

    private void makeLeaf(int node, int start, int count) {
        data[2 * node] = start;
        data[2 * node + 1] = count;
        leafCount++;
    }

    static double surfaceArea(double x0, double y0, double z0, double x1, double y1, double z1) {
        double ex = x1 - x0, ey = y1 - y0, ez = z1 - z0;
        return 2 * (ex * ey + ey * ez + ez * ex);
    }
}
