package geometries;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The binned-SAH build of a {@link BVH}'s binary tree: at each node the centroids are binned along the axis of
 * largest centroid extent and the cheapest bin boundary is taken unless a leaf is cheaper; nodes are written
 * depth-first into arrays sized once for the 2n - 1 nodes a binary tree can have. Large inputs build their
 * subtrees in parallel, into the very tree the sequential build gives. {@link BVH} then collapses it into wide
 * nodes.
 */
final class BvhBuilder {
    private final double[] primBounds;
    final int[] index;
    private final int bins;
    private final int maxLeafSize;
    private final int[] binCount;
    private final double[] binBounds;
    private final double[] rightArea;
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
        this(primBounds, grouped(primBounds.length / 6, secondGroup), bins, maxLeafSize, primBounds.length / 6);
        int n = index.length;
        int split = firstOfSecondGroup(n, secondGroup);
        grouped = split > 0;
        if (grouped) {
            // The forced root over the two groups' trees, laid out as the parallel build lays out its top.
            List<Subtree> subtrees = new ArrayList<>();
            Object left = parallel ? plan(0, split, 1, subtrees) : new Subtree(0, split, 1);
            Object right = parallel ? plan(split, n, 1, subtrees) : new Subtree(split, n, 1);
            if (!parallel) {
                subtrees.add((Subtree) left);
                subtrees.add((Subtree) right);
            }
            (parallel ? subtrees.parallelStream() : subtrees.stream()).forEach(Subtree::build);
            float[] box = boxOf(left).clone(), other = boxOf(right);
            // Minima and maxima of boxes already rounded outward: the box of the union, rounded outward.
            for (int a = 0; a < 3; a++) {
                box[a] = Math.min(box[a], other[a]);
                box[3 + a] = Math.max(box[3 + a], other[3 + a]);
            }
            emit(new Split(box, 0, left, right));
        } else if (parallel && n >= 2 * BVH.PARALLEL_GRAIN) {
            buildInParallel(n);
        } else if (n > 0) {
            build(0, n, 0);
        }
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
        return Arrays.copyOf(((Subtree) planned).builder.bounds, 6);
    }

    /** A builder for a subtree over {@code primitives} primitives of a shared {@code index}. */
    private BvhBuilder(double[] primBounds, int[] index, int bins, int maxLeafSize, int primitives) {
        this.primBounds = primBounds;
        this.index = index;
        this.bins = bins;
        this.maxLeafSize = maxLeafSize;
        binCount = new int[bins];
        binBounds = new double[6 * bins];
        rightArea = new double[bins];
        // A binary tree over n primitives has at most 2n - 1 nodes (leaves hold at least one), so the arrays are
        // allocated once: growing them by doubling allocated and copied twice the memory on large meshes.
        int capacity = Math.max(1, 2 * primitives - 1);
        bounds = new float[6 * capacity];
        data = new int[2 * capacity];
    }

    private static int[] identity(int n) {
        int[] index = new int[n];
        for (int i = 0; i < n; i++) index[i] = i;
        return index;
    }

    /**
     * The parallel build: the top of the tree is split here exactly as {@link #build} would split it, down to
     * ranges of at most {@link #BVH.PARALLEL_GRAIN} primitives; those subtrees are built on the common fork/join
     * pool, each by its own builder into its own arrays (they partition disjoint ranges of the shared index);
     * then everything is laid out depth-first as the sequential build numbers it. The tree is therefore
     * identical, bit for bit, to the sequential one, whatever the number of cores.
     */
    private void buildInParallel(int n) {
        List<Subtree> subtrees = new ArrayList<>();
        Object top = plan(0, n, 0, subtrees);
        subtrees.parallelStream().forEach(Subtree::build);
        emit(top);
    }

    /** A range the parallel build hands to a builder of its own. */
    private final class Subtree {
        final int start, end, depth;
        BvhBuilder builder;

        Subtree(int start, int end, int depth) {
            this.start = start;
            this.end = end;
            this.depth = depth;
        }

        void build() {
            builder = new BvhBuilder(primBounds, index, bins, maxLeafSize, end - start);
            builder.build(start, end, depth);
        }
    }

    /** An interior node of the top of the tree: its rounded box, split axis and two children. */
    private record Split(float[] box, int axis, Object left, Object right) {}

    /** Splits {@code [start, end)} as {@link #build} would, down to subtrees; returns a Split or a Subtree. */
    private Object plan(int start, int end, int depth, List<Subtree> subtrees) {
        float[] box = new float[6];
        int[] axis = new int[1];
        int mid = end - start <= BVH.PARALLEL_GRAIN ? -1 : split(start, end, depth, box, axis);
        if (mid < 0) {
            Subtree subtree = new Subtree(start, end, depth);
            subtrees.add(subtree);
            return subtree;
        }
        Object left = plan(start, mid, depth + 1, subtrees);
        return new Split(box, axis[0], left, plan(mid, end, depth + 1, subtrees));
    }

    /** Lays out a planned node and everything below it at the next node index, depth-first. */
    private void emit(Object planned) {
        if (planned instanceof Subtree subtree) {
            BvhBuilder b = subtree.builder;
            int offset = nodeCount;
            System.arraycopy(b.bounds, 0, bounds, 6 * offset, 6 * b.nodeCount);
            for (int i = 0; i < b.nodeCount; i++) {
                int link = b.data[2 * i], kind = b.data[2 * i + 1];
                // Interior nodes link to their second child by node index; leaves to primitive positions.
                data[2 * (offset + i)] = kind < 0 ? link + offset : link;
                data[2 * (offset + i) + 1] = kind;
            }
            nodeCount += b.nodeCount;
            leafCount += b.leafCount;
            maxDepthReached = Math.max(maxDepthReached, b.maxDepthReached);
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

    private void build(int start, int end, int depth) {
        int node = allocateNode();
        int[] axis = this.axis;
        int mid = split(start, end, depth, bounds, 6 * node, axis);
        if (mid < 0) {
            makeLeaf(node, start, end - start);
            return;
        }
        build(start, mid, depth + 1);
        int second = nodeCount;
        build(mid, end, depth + 1);
        data[2 * node] = second;
        data[2 * node + 1] = -1 - axis[0];
    }

    /** {@link #split(int, int, int, float[], int, int[])} writing the box to the start of {@code box}. */
    private int split(int start, int end, int depth, float[] box, int[] axis) {
        return split(start, end, depth, box, 0, axis);
    }

    /**
     * Decides the node over {@code [start, end)}: writes its box rounded outward to {@code box[at..at+6)}, and
     * either returns -1 for a leaf or partitions the range and returns the split position, with the split axis
     * in {@code axisOut[0]}.
     */
    private int split(int start, int end, int depth, float[] box, int at, int[] axisOut) {
        int count = end - start;
        // Node bounds and centroid bounds in one pass.
        double bx0 = Double.POSITIVE_INFINITY, by0 = bx0, bz0 = bx0;
        double bx1 = Double.NEGATIVE_INFINITY, by1 = bx1, bz1 = bx1;
        double cx0 = Double.POSITIVE_INFINITY, cy0 = cx0, cz0 = cx0;
        double cx1 = Double.NEGATIVE_INFINITY, cy1 = cx1, cz1 = cx1;
        for (int k = start; k < end; k++) {
            int p = index[k];
            int o = 6 * p;
            bx0 = Math.min(bx0, primBounds[o]);
            by0 = Math.min(by0, primBounds[o + 1]);
            bz0 = Math.min(bz0, primBounds[o + 2]);
            bx1 = Math.max(bx1, primBounds[o + 3]);
            by1 = Math.max(by1, primBounds[o + 4]);
            bz1 = Math.max(bz1, primBounds[o + 5]);
            double x = 0.5 * (primBounds[o] + primBounds[o + 3]);
            double y = 0.5 * (primBounds[o + 1] + primBounds[o + 4]);
            double z = 0.5 * (primBounds[o + 2] + primBounds[o + 5]);
            cx0 = Math.min(cx0, x);
            cy0 = Math.min(cy0, y);
            cz0 = Math.min(cz0, z);
            cx1 = Math.max(cx1, x);
            cy1 = Math.max(cy1, y);
            cz1 = Math.max(cz1, z);
        }
        box[at] = BVH.floatBelow(bx0);
        box[at + 1] = BVH.floatBelow(by0);
        box[at + 2] = BVH.floatBelow(bz0);
        box[at + 3] = BVH.floatAbove(bx1);
        box[at + 4] = BVH.floatAbove(by1);
        box[at + 5] = BVH.floatAbove(bz1);
        maxDepthReached = Math.max(maxDepthReached, depth);

        if (count == 1 || depth >= BVH.MAX_DEPTH) return -1;
        double ex = cx1 - cx0, ey = cy1 - cy0, ez = cz1 - cz0;
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        axisOut[0] = axis;
        double lo = axis == 0 ? cx0 : axis == 1 ? cy0 : cz0;
        double extent = axis == 0 ? ex : axis == 1 ? ey : ez;
        if (!(extent > 0)) {
            // All centroids coincide: nothing separates them, so split by count to keep leaves small.
            return count <= maxLeafSize ? -1 : start + count / 2;
        }
        return sahPartition(start, end, axis, lo, extent, surfaceArea(bx0, by0, bz0, bx1, by1, bz1), count);
    }

    /** Partitions by the cheapest bin boundary; returns the split position, or -1 if a leaf is better. */
    private int sahPartition(int start, int end, int axis, double lo, double extent, double nodeArea, int count) {
        Arrays.fill(binCount, 0);
        for (int i = 0; i < bins; i++) {
            int o = 6 * i;
            binBounds[o] = binBounds[o + 1] = binBounds[o + 2] = Double.POSITIVE_INFINITY;
            binBounds[o + 3] = binBounds[o + 4] = binBounds[o + 5] = Double.NEGATIVE_INFINITY;
        }
        double scale = bins / extent;
        for (int k = start; k < end; k++) {
            int p = index[k];
            int bin = binOf(centroid(p, axis), lo, scale);
            binCount[bin]++;
            int o = 6 * bin, q = 6 * p;
            binBounds[o] = Math.min(binBounds[o], primBounds[q]);
            binBounds[o + 1] = Math.min(binBounds[o + 1], primBounds[q + 1]);
            binBounds[o + 2] = Math.min(binBounds[o + 2], primBounds[q + 2]);
            binBounds[o + 3] = Math.max(binBounds[o + 3], primBounds[q + 3]);
            binBounds[o + 4] = Math.max(binBounds[o + 4], primBounds[q + 4]);
            binBounds[o + 5] = Math.max(binBounds[o + 5], primBounds[q + 5]);
        }
        // Sweep from the right: area of the union of bins [i, bins).
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = bins - 1; i > 0; i--) {
            int o = 6 * i;
            x0 = Math.min(x0, binBounds[o]);
            y0 = Math.min(y0, binBounds[o + 1]);
            z0 = Math.min(z0, binBounds[o + 2]);
            x1 = Math.max(x1, binBounds[o + 3]);
            y1 = Math.max(y1, binBounds[o + 4]);
            z1 = Math.max(z1, binBounds[o + 5]);
            rightArea[i] = surfaceArea(x0, y0, z0, x1, y1, z1);
        }
        // Sweep from the left, pricing the split after bin i.
        x0 = y0 = z0 = Double.POSITIVE_INFINITY;
        x1 = y1 = z1 = Double.NEGATIVE_INFINITY;
        int leftCount = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1;
        for (int i = 0; i < bins - 1; i++) {
            int o = 6 * i;
            x0 = Math.min(x0, binBounds[o]);
            y0 = Math.min(y0, binBounds[o + 1]);
            z0 = Math.min(z0, binBounds[o + 2]);
            x1 = Math.max(x1, binBounds[o + 3]);
            y1 = Math.max(y1, binBounds[o + 4]);
            z1 = Math.max(z1, binBounds[o + 5]);
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
            return count <= maxLeafSize ? -1 : start + count / 2;
        }
        if (count <= maxLeafSize && splitCost >= count) return -1;
        // Partition in place: bins [0, bestSplit] to the left.
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
