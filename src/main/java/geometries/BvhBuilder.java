package geometries;

import static geometries.SahSplitter.SUMMARY;

import java.util.Arrays;
import java.util.concurrent.ForkJoinTask;

/**
 * The build of a {@link BVH}'s binary tree, each node decided by a {@link SahSplitter} (binned SAH); nodes are
 * written depth-first, a sequential build into arrays sized once for the 2n - 1 nodes a binary tree can have.
 * Large inputs split their top on a fork/join pool and build their subtrees in parallel, into the very tree the
 * sequential build gives. {@link BVH} then collapses it into wide nodes.
 */
final class BvhBuilder {
    private final float[] boxes;
    final int[] index;
    private final int bins;
    private final int maxLeafSize;
    /** The small groups made leaves whatever the SAH says (within {@link #maxLeafSize}). */
    private final FilledLeaves filled;
    /** Decides this builder's nodes. */
    private final SahSplitter splitter;

    /**
     * Six floats per node, its box rounded outward ({@link FloatBoxes#floatBelow}, {@link FloatBoxes#floatAbove}): all
     * the collapse and the traversal need, at half the memory of doubles.
     */
    float[] bounds;

    /**
     * Two ints per node: a leaf's first primitive (in {@link #index}) and its count, positive; an interior node's
     * second child (its first follows it) and {@code -1 - axis} of its split.
     */
    int[] data;

    int nodeCount;
    int leafCount;
    int maxDepthReached;

    /**
     * Whether the root divides the primitives into the two groups of {@link #BvhBuilder(float[], int, int, boolean,
     * boolean[])}: its first child holds the first group, its second child the second.
     */
    boolean grouped;

    /**
     * Builds the tree; with {@code secondGroup} naming some but not all primitives, the root's two children are
     * the trees of the other primitives and of those (each built as usual), so a query that needs only the first
     * group can leave the second's subtree out.
     */
    BvhBuilder(float[] boxes, int bins, int maxLeafSize, FilledLeaves filled, boolean parallel, boolean[] secondGroup) {
        this(boxes, grouped(boxes.length / BVH.BOX_STRIDE, secondGroup), bins, maxLeafSize, filled);
        int n = index.length;
        int split = firstOfSecondGroup(n, secondGroup);
        grouped = split > 0;
        if (grouped) {
            // The forced root over the two groups' trees, laid out as the parallel build lays out its top.
            double[] groups = new double[2 * SUMMARY];
            splitter.summarize(0, split, groups, 0);
            splitter.summarize(split, n, groups, SUMMARY);
            Object top;
            if (parallel) {
                top = BuildPool.invoke(() -> {
                    ForkJoinTask<Object> left = ForkJoinTask.adapt(() -> plan(0, split, 1, groups, 0))
                            .fork();
                    Object right = plan(split, n, 1, groups, SUMMARY);
                    return groupRoot(left.join(), right);
                });
            } else {
                top = groupRoot(subtree(0, split, 1, groups, 0), subtree(split, n, 1, groups, SUMMARY));
            }
            emitAll(top);
        } else if (n > 0) {
            double[] root = new double[SUMMARY];
            splitter.summarize(0, n, root, 0);
            if (parallel && n >= 2 * BVH.PARALLEL_GRAIN) {
                emitAll(BuildPool.invoke(() -> plan(0, n, 0, root, 0)));
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
    private BvhBuilder(float[] boxes, int[] index, int bins, int maxLeafSize, FilledLeaves filled) {
        this.boxes = boxes;
        this.index = index;
        this.bins = bins;
        this.maxLeafSize = maxLeafSize;
        this.filled = filled;
        splitter = new SahSplitter(boxes, index, bins, maxLeafSize, filled);
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
     * Each worker of the {@link BuildPool} builds its subtrees in the same room and copies each out at its final size,
     * instead of allocating every subtree the 2n - 1 nodes it might need.
     */
    private static final ThreadLocal<Room> ROOM = ThreadLocal.withInitial(Room::new);

    /** Builds {@code [start, end)} (summarized at {@code summary[at..]}) by a builder of its own. */
    private Subtree subtree(int start, int end, int depth, double[] summary, int at) {
        BvhBuilder builder = new BvhBuilder(boxes, index, bins, maxLeafSize, filled);
        if (end - start <= BVH.PARALLEL_GRAIN && BuildPool.isWorker()) {
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
        SahSplitter top = new SahSplitter(boxes, index, bins, maxLeafSize, filled);
        float[] box = new float[6];
        SahSplitter.roundedBox(summary, at, box, 0);
        int mid = top.split(start, end, depth, summary, at);
        if (mid < 0) return subtree(start, end, depth, summary, at);
        int axis = top.splitAxis;
        int first = SahSplitter.childrenAt(depth);
        double[] children = Arrays.copyOfRange(top.childSummaries, first, first + 2 * SUMMARY);
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

    /** Whether node {@code node} is a leaf. */
    boolean isLeaf(int node) {
        return data[2 * node + 1] > 0;
    }

    /** The surface area of node {@code node}'s box. */
    double area(int node) {
        int o = 6 * node;
        return SahSplitter.surfaceArea(
                bounds[o], bounds[o + 1], bounds[o + 2], bounds[o + 3], bounds[o + 4], bounds[o + 5]);
    }

    /**
     * What opening each binary node is worth to the wide collapse: its box's surface area times the primitives below
     * it, the SAH's estimate of the work below it; -1 for a leaf, which cannot be opened.
     *
     * @return one weight per node of the finished tree
     */
    double[] workBelow() {
        // Children follow their parents in depth-first order: one backward sweep sums every subtree.
        int[] below = new int[nodeCount];
        double[] work = new double[nodeCount];
        for (int i = nodeCount - 1; i >= 0; i--) {
            int count = data[2 * i + 1];
            below[i] = count > 0 ? count : below[i + 1] + below[data[2 * i]];
            work[i] = count > 0 ? -1 : area(i) * below[i];
        }
        return work;
    }

    private int allocateNode() {
        return nodeCount++;
    }

    /** Builds the subtree over {@code [start, end)}, summarized at {@code summary[at..]}, at the next node index. */
    private void build(int start, int end, int depth, double[] summary, int at) {
        int node = allocateNode();
        SahSplitter.roundedBox(summary, at, bounds, 6 * node);
        maxDepthReached = Math.max(maxDepthReached, depth);
        int mid = splitter.split(start, end, depth, summary, at);
        if (mid < 0) {
            makeLeaf(node, start, end - start);
            return;
        }
        int splitAxis = splitter.splitAxis;
        double[] childSummaries = splitter.childSummaries;
        int children = SahSplitter.childrenAt(depth);
        build(start, mid, depth + 1, childSummaries, children);
        int second = nodeCount;
        build(mid, end, depth + 1, childSummaries, children + SUMMARY);
        data[2 * node] = second;
        data[2 * node + 1] = -1 - splitAxis;
    }

    private void makeLeaf(int node, int start, int count) {
        data[2 * node] = start;
        data[2 * node + 1] = count;
        leafCount++;
    }
}
