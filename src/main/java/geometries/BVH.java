package geometries;

import java.util.ArrayList;
import java.util.List;

/**
 * A bounding volume hierarchy built top-down with a binned surface-area heuristic as a binary tree, then collapsed
 * into an 8-wide tree (Embree's BVH8 and pbrt-v4's wide-BVH layout) and flattened depth-first into one float array.
 *
 * <p>Each 8-wide node is 256 bytes: the boxes of its (up to) eight children in structure-of-arrays form, as floats
 * rounded outward so box tests stay conservative ({@code minX[8], minY[8], minZ[8], maxX[8], maxY[8], maxZ[8]}),
 * then per child a link and a count. A child with a count is a leaf holding that many primitives of the leaf
 * order from its link; a child with count 0 is the node its link names. Unused slots hold an empty box (min
 * {@code +inf}, max {@code -inf}) that every ray misses. The first interior child of a node follows it in the
 * array (depth-first order).
 *
 * <p>Keeping the eight child boxes in the parent lets the traversal test them in one 256-bit vector operation per
 * plane (AVX2: eight floats) and visit the nearest first; the 8-wide tree has about a third of the depth of the
 * binary one, so a ray makes fewer dependent node fetches and stack operations (see docs/BENCHMARKS.md: against
 * the former 4-wide double kernel it wins most on small scenes and incoherent rays).
 *
 * <p>Build ({@link BvhBuilder}, each node decided by {@link SahSplitter}): at each binary node the centroids are binned
 * along the axis of largest centroid extent; the split between bins that minimises {@code 1 + (nL aL + nR aR) / a} is
 * taken unless a leaf (cost {@code n}) is cheaper and small enough. Nodes whose centroids coincide are halved by count
 * so leaves stay bounded. The binary tree is then collapsed ({@link WideCollapser}): optimally (least total area of
 * wide nodes) in subtrees of up to 512 leaves, greedily above (a wide node starts from a binary node's two children
 * and repeatedly replaces the interior child with the most work below it, surface area times primitives, by its two
 * children until it has eight). A build may give a group of primitives (Accelerator's clear surfaces) a subtree of
 * its own under the root, which {@link #secondGroupSlots} names. The traversals live
 * beside the primitive data they test, in the package-private ClosestHitTraversal and ShadowQueries of
 * {@link Accelerator}.
 */
public final class BVH {
    /** Deepest node level of the binary tree (and so of the wide tree); the traversal stack is sized from it. */
    public static final int MAX_DEPTH = 64;
    /** Children per node of the traversal tree. */
    public static final int WIDTH = 8;
    /** Entries the traversal stack may need: each node visited pushes at most {@code WIDTH - 1} more. */
    static final int STACK_SIZE = (WIDTH - 1) * MAX_DEPTH + 2;
    /**
     * Cost of visiting a node relative to testing a primitive. pbrt-v4 uses 0.5; here a visit tests both child
     * boxes, which the JMH kernels put at about one watertight triangle test, and 1.0 measured faster on the
     * icosphere (fewer, fuller leaves) and the same on the heightfield.
     */
    static final double TRAVERSAL_COST = 1.0;
    /**
     * Primitives below which a subtree is built by one thread: large enough that scheduling costs nothing, small
     * enough that a million primitives give a few dozen tasks to balance.
     */
    static final int PARALLEL_GRAIN = 32_768;

    /**
     * Floats per primitive box given to the float build ({@link PrimitiveCollector#boxes}): the minimum corner x, y, z
     * and an unused fourth, then the maximum corner likewise, so that one vector load reads a corner.
     */
    static final int BOX_STRIDE = 8;
    /** Offset of a box's maximum corner in its {@link #BOX_STRIDE} floats. */
    static final int BOX_MAX = 4;

    /** Floats per node in {@link #nodes}. */
    static final int NODE_STRIDE = 8 * WIDTH;
    /** Offsets of the children's box coordinates in a node: child c's minX is at {@code MIN_X + c}, and so on. */
    static final int MIN_X = 0,
            MIN_Y = WIDTH,
            MIN_Z = 2 * WIDTH,
            MAX_X = 3 * WIDTH,
            MAX_Y = 4 * WIDTH,
            MAX_Z = 5 * WIDTH;
    /** Offsets of the children's links and counts (int bits): child c's link is at {@code LINK + c}. */
    static final int LINK = 6 * WIDTH, COUNT = 7 * WIDTH;

    /**
     * Floats in {@link #nodes} before the first node, so that every node's 256 bytes fill four cache lines instead
     * of straddling five. HotSpot's default collector (G1) places an array of half a heap region or more at the start
     * of a region, its data 16 bytes in (nodes of 1 MB, some 60,000 triangles, with the 2 MB regions of a 4-8 GB
     * heap: the trees that outgrow the caches); 12 floats more put node 0, and every node after it, on a 64-byte
     * boundary. Elsewhere an array's address is arbitrary and the 48 bytes change nothing.
     */
    static final int FIRST_NODE = 12;

    /** Where wide node {@code link}'s floats start in {@link #nodes}. */
    static int nodeOffset(int link) {
        return FIRST_NODE + NODE_STRIDE * link;
    }

    /**
     * Node i in the 64 floats from {@link #nodeOffset}(i): the six box coordinates of children 0..7 coordinate by
     * coordinate, then the eight links and the eight counts stored as float bits ({@link Float#intBitsToFloat}; the
     * values are non-negative ints, so no NaN pattern arises).
     */
    final float[] nodes;
    /** The root's box (rounded outward) and the root as a child: a leaf if {@link #rootCount} is positive. */
    final float[] rootBounds = new float[6];

    final int rootLink, rootCount;
    /**
     * With primitive groups ({@link #build(double[], int, int, boolean[])}): the slots of the root node whose subtrees
     * hold only the second group (a bit per slot), else 0.
     */
    final int secondGroupSlots;
    /** The primitives in leaf order: entry k is the original index of the k-th primitive. */
    final int[] order;

    private final int binaryNodeCount;
    private final int leafCount;
    private final int maxDepth;
    private final int wideNodeCount;

    /** Collapses the binary tree of {@code b}; {@code parallel}: a large tree's root subtrees on all cores. */
    private BVH(BvhBuilder b, boolean parallel) {
        this.binaryNodeCount = b.nodeCount;
        this.leafCount = b.leafCount;
        this.maxDepth = b.maxDepthReached;
        this.order = b.index;
        boolean rootIsLeaf = b.isLeaf(0);
        boolean large = parallel && b.nodeCount >= 2 * PARALLEL_GRAIN;
        WideCollapser c = new WideCollapser(b, large);
        if (rootIsLeaf) {
            c.allocate(0);
        } else if (large) {
            c.collapseInParallel();
        } else {
            c.allocate(c.countWideNodes(0));
            c.collapse(0);
        }
        nodes = c.nodes;
        wideNodeCount = c.count;
        secondGroupSlots = b.grouped ? c.slotsFrom(b.data[0]) : 0;
        System.arraycopy(b.bounds, 0, rootBounds, 0, 6);
        rootLink = rootIsLeaf ? b.data[0] : 0;
        rootCount = rootIsLeaf ? b.data[1] : 0;
    }

    /**
     * Builds a BVH over primitives given by their boxes.
     *
     * @param primitiveBounds six doubles per primitive: min x, y, z then max x, y, z
     * @param bins number of SAH bins per node, 2..256
     * @param maxLeafSize most primitives a leaf may hold unless their centroids coincide, 1..64
     * @return the new BVH
     * @throws IllegalArgumentException if {@code bins} or {@code maxLeafSize} is out of range, or the bounds are empty or
     *     not six values per primitive
     */
    public static BVH build(double[] primitiveBounds, int bins, int maxLeafSize) {
        // One core gains nothing from the parallel path (the tree is the same either way).
        return build(primitiveBounds, bins, maxLeafSize, Runtime.getRuntime().availableProcessors() > 1);
    }

    /**
     * {@link #build(double[], int, int)}, on one thread unless {@code parallel}: the trees are identical, which
     * the tests check.
     */
    static BVH build(double[] primitiveBounds, int bins, int maxLeafSize, boolean parallel) {
        return build(primitiveBounds, bins, maxLeafSize, parallel, null);
    }

    /**
     * {@link #build(double[], int, int)} with the primitives of {@code secondGroup} in a subtree of their own under
     * the root (when some but not all are in it), which {@link #secondGroupSlots} names: a query that needs no
     * primitive of the group skips that subtree at the root. Accelerator's shadow queries skip clear surfaces so.
     */
    static BVH build(double[] primitiveBounds, int bins, int maxLeafSize, boolean[] secondGroup) {
        return build(primitiveBounds, bins, maxLeafSize, Runtime.getRuntime().availableProcessors() > 1, secondGroup);
    }

    /**
     * {@link #build(float[], int, int, boolean, boolean[])}, in parallel where there is more than one core, with the
     * groups {@code filled} names (within {@code maxLeafSize}) made leaves whatever the SAH says: the accelerator's,
     * whose {@link LeafFilter} tests a leaf of up to four triangles in one call.
     */
    static BVH build(float[] primitiveBounds, int bins, int maxLeafSize, FilledLeaves filled, boolean[] secondGroup) {
        return build(
                primitiveBounds,
                bins,
                maxLeafSize,
                filled,
                Runtime.getRuntime().availableProcessors() > 1,
                secondGroup);
    }

    static BVH build(double[] primitiveBounds, int bins, int maxLeafSize, boolean parallel, boolean[] secondGroup) {
        return build(FloatBoxes.roundedOutward(primitiveBounds), bins, maxLeafSize, parallel, secondGroup);
    }

    /**
     * {@link #build(double[], int, int, boolean, boolean[])} over boxes already in floats ({@link #BOX_STRIDE} per
     * primitive), each holding its primitive ({@link FloatBoxes#roundedOutward}, or padded as {@link
     * PrimitiveCollector#boxes} gives them): the builder reads nothing else, and half the bytes of doubles per
     * primitive and pass made the 1M heightfield's binary tree about 1.05-1.1x faster (docs/BENCHMARKS.md, 27 Nov).
     * Bounds at -0.0 are set to 0.0 in place (the same boxes), as {@link PrimitiveBinning#bin} requires.
     */
    static BVH build(float[] primitiveBounds, int bins, int maxLeafSize, boolean parallel, boolean[] secondGroup) {
        return build(primitiveBounds, bins, maxLeafSize, FilledLeaves.NONE, parallel, secondGroup);
    }

    /** {@link #build(float[], int, int, boolean, boolean[])} with the groups {@code filled} names made leaves. */
    static BVH build(
            float[] primitiveBounds,
            int bins,
            int maxLeafSize,
            FilledLeaves filled,
            boolean parallel,
            boolean[] secondGroup) {
        validateSettings(bins, maxLeafSize);
        FloatBoxes.checkAndNormalize(primitiveBounds, parallel);
        return new BVH(new BvhBuilder(primitiveBounds, bins, maxLeafSize, filled, parallel, secondGroup), parallel);
    }

    /** Throws unless {@code bins} is in [2, 256] and {@code maxLeafSize} in [1, 64]. */
    static void validateSettings(int bins, int maxLeafSize) {
        if (bins < 2 || bins > 256) {
            throw new IllegalArgumentException("BVH bins must be in [2, 256], but was " + bins);
        }
        if (maxLeafSize < 1 || maxLeafSize > 64) {
            throw new IllegalArgumentException("BVH maxLeafSize must be in [1, 64], but was " + maxLeafSize);
        }
    }

    /**
     * Nodes of the traversal tree, leaves included: wide interior nodes plus leaves.
     *
     * @return the number of wide interior nodes plus leaves
     */
    public int nodeCount() {
        return wideNodeCount + leafCount;
    }

    /**
     * Interior nodes of the binary SAH tree the traversal tree was collapsed from, plus its leaves.
     *
     * @return the number of binary interior nodes plus leaves
     */
    public int binaryNodeCount() {
        return binaryNodeCount;
    }

    /**
     * The number of leaves.
     *
     * @return the leaf count
     */
    public int leafCount() {
        return leafCount;
    }

    /**
     * Depth of the deepest leaf of the binary SAH tree (the root is depth 0).
     *
     * @return the depth, 0 for a single leaf
     */
    public int depth() {
        return maxDepth;
    }

    /**
     * The number of primitives the BVH was built over.
     *
     * @return the primitive count
     */
    public int primitiveCount() {
        return order.length;
    }

    /**
     * Bytes held by the node and order arrays.
     *
     * @return the size in bytes
     */
    public long bytes() {
        return 4L * nodes.length + 4L * order.length + 4L * rootBounds.length;
    }

    /**
     * The box around everything in the tree.
     *
     * @return a new box around all primitives
     */
    public BoundingBox bounds() {
        return new BoundingBox(
                rootBounds[0], rootBounds[1], rootBounds[2], rootBounds[3], rootBounds[4], rootBounds[5]);
    }

    /**
     * Node {@code i} of the traversal tree in depth-first order (0 is the root), for inspection and tests: it walks
     * the whole tree, so prefer {@link #nodes()} to look at many.
     *
     * @param i the node's depth-first index, from 0 to {@link #nodeCount()} - 1
     * @return a new view of the node
     * @throws IllegalArgumentException if {@code i} is out of range
     */
    public BVHNode node(int i) {
        if (i < 0 || i >= nodeCount()) {
            throw new IllegalArgumentException("node index must be in [0, " + nodeCount() + "), but was " + i);
        }
        return nodes().get(i);
    }

    /**
     * All nodes of the traversal tree in depth-first order, leaves included (allocates; for inspection and tests).
     *
     * @return a new list of node views, the root first
     */
    public List<BVHNode> nodes() {
        List<BVHNode> list = new ArrayList<>(nodeCount());
        collect(bounds(), rootLink, rootCount, list);
        return list;
    }

    private void collect(BoundingBox box, int link, int count, List<BVHNode> list) {
        if (count > 0) {
            list.add(new BVHNode(box, link, count, List.of()));
            return;
        }
        int self = list.size();
        list.add(null); // replaced once the children's indices are known
        int o = nodeOffset(link);
        List<Integer> children = new ArrayList<>(WIDTH);
        for (int c = 0; c < WIDTH; c++) {
            if (!(nodes[o + MIN_X + c] <= nodes[o + MAX_X + c])) continue; // an unused slot
            children.add(list.size());
            BoundingBox childBox = new BoundingBox(
                    nodes[o + MIN_X + c],
                    nodes[o + MIN_Y + c],
                    nodes[o + MIN_Z + c],
                    nodes[o + MAX_X + c],
                    nodes[o + MAX_Y + c],
                    nodes[o + MAX_Z + c]);
            collect(childBox, intAt(o + LINK + c), intAt(o + COUNT + c), list);
        }
        list.set(self, new BVHNode(box, -1, 0, List.copyOf(children)));
    }

    private int intAt(int i) {
        return Float.floatToRawIntBits(nodes[i]);
    }

    /**
     * Original index of the primitive at position {@code k} of the leaf order.
     *
     * @param k the 0-based position in the leaf order, below {@link #primitiveCount()}
     * @return the primitive's index in the bounds array given to {@link #build}
     */
    public int primitiveAt(int k) {
        return order[k];
    }
}
