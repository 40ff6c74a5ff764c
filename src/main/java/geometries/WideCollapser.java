package geometries;

import static geometries.BVH.COUNT;
import static geometries.BVH.LINK;
import static geometries.BVH.MAX_X;
import static geometries.BVH.MIN_X;
import static geometries.BVH.NODE_STRIDE;
import static geometries.BVH.WIDTH;

import java.util.Arrays;

/**
 * Collapses a {@link BvhBuilder}'s binary tree into the wide nodes of a {@link BVH}, written depth-first. Which binary
 * nodes become wide nodes is decided two ways:
 *
 * <ul>
 *   <li>Below {@link #GREEDY_ABOVE} leaves, optimally: of all the ways to collapse the subtree, the one whose wide
 *       nodes have the least total surface area, the SAH's cost of the node visits (the leaves are the binary tree's
 *       whatever the collapse, so their cost is fixed), found by dynamic programming over the number of slots a
 *       subtree takes in its parent ({@link #planSubtree}; the optimal conversion of Ylitie, Karras and Laine's
 *       compressed wide BVHs, 2017, with the leaves given). Near the leaves a greedy collapse leaves nodes half
 *       empty: the 1.3M-triangle icosphere's tree had 172,101 wide nodes for 407,465 leaves; 80,094 with this.
 *   <li>Above it, greedily: a wide node starts from a binary node's two children and repeatedly opens the interior
 *       child with the most work below it (its box's surface area times its primitives) until it has {@link
 *       BVH#WIDTH} children. The SAH's area assumes rays spread evenly over the scene's box, which a camera inside a
 *       scene does not see: at the top of the street the optimal collapse made camera rays visit 8% more boxes.
 * </ul>
 */
final class WideCollapser {
    /**
     * Subtrees of at most this many leaves (8^3: the bottom three levels of full wide nodes) are collapsed optimally,
     * larger ones greedily.
     */
    static final int GREEDY_ABOVE = 512;
    /** Subtrees planned per task of the parallel plan. */
    private static final int PLAN_CHUNK = 64;

    private final BvhBuilder b;
    /**
     * What opening each binary node is worth to the greedy collapse: its box's surface area times its primitives, the
     * SAH's estimate of the work below it. Area alone (Embree's choice) spends root slots on the few huge, far objects
     * of a scene such as the street's moon and clouds, and leaves the street itself for the next level.
     */
    private final double[] work;
    /** Subtrees of more leaves are collapsed greedily: {@link #GREEDY_ABOVE}, but for tests. */
    private final int greedyAbove;
    /** Leaves below each binary node. */
    private final int[] leaves;
    /**
     * The optimal collapse's choices, for binary interior node i of at most {@link #GREEDY_ABOVE} leaves taking at
     * most j + 1 slots of its parent (j below seven): {@code split[WIDTH i + j]} is 0 where the node takes one slot
     * itself (a wide node), else the slots its first child's subtree takes (its second child's take the rest).
     */
    private final byte[] split;
    /** For such a node as a wide node: the slots of its eight that its first child's subtree takes. */
    private final byte[] ownSplit;

    float[] nodes;
    int count;

    /** Plans the collapse of {@code b}'s tree; {@code parallel}: the optimal subtrees planned on all cores. */
    WideCollapser(BvhBuilder b, boolean parallel) {
        this(b, parallel, GREEDY_ABOVE);
    }

    /** The same with subtrees of more than {@code greedyAbove} leaves collapsed greedily (tests compare the two). */
    WideCollapser(BvhBuilder b, boolean parallel, int greedyAbove) {
        this.b = b;
        this.greedyAbove = greedyAbove;
        int n = b.nodeCount;
        leaves = new int[n];
        // Children follow their parents in depth-first order: one backward sweep counts every subtree's leaves.
        for (int i = n - 1; i >= 0; i--) leaves[i] = b.isLeaf(i) ? 1 : leaves[i + 1] + leaves[b.data[2 * i]];
        work = leaves[0] > greedyAbove ? b.workBelow() : null;
        split = new byte[WIDTH * n];
        ownSplit = new byte[n];
        int[] optimal = new int[leaves[0]];
        int roots = optimalRoots(0, optimal, 0);
        // One scratch array per chunk of subtrees, not per subtree: a million-triangle tree has a thousand or more.
        BuildPool.forEachChunk(roots, PLAN_CHUNK, parallel, (chunk, from, to) -> {
            float[] cost = new float[WIDTH * (2 * greedyAbove - 1)];
            for (int r = from; r < to; r++) planSubtree(optimal[r], cost);
        });
    }

    /** A collapser writing into {@code whole}'s nodes from wide node {@code first} on (a subtree of the root). */
    private WideCollapser(WideCollapser whole, int first) {
        b = whole.b;
        greedyAbove = whole.greedyAbove;
        work = whole.work;
        leaves = whole.leaves;
        split = whole.split;
        ownSplit = whole.ownSplit;
        nodes = whole.nodes;
        count = first;
    }

    /**
     * {@link #collapse collapse(0)} with the root's subtrees counted and written on all cores: each is given the
     * range of wide nodes the sequential collapse would give it, so the array is the same bit for bit.
     */
    void collapseInParallel() {
        int[] children = new int[WIDTH];
        int n = open(0, children);
        int[] sizes = new int[n];
        BuildPool.forEach(n, true, c -> {
            if (!b.isLeaf(children[c])) sizes[c] = countWideNodes(children[c]);
        });
        int[] links = new int[n];
        int next = 1;
        for (int c = 0; c < n; c++) {
            links[c] = b.isLeaf(children[c]) ? b.data[2 * children[c]] : next;
            next += sizes[c];
        }
        allocate(next);
        BuildPool.forEach(n, true, c -> {
            if (!b.isLeaf(children[c])) new WideCollapser(this, links[c]).collapse(children[c]);
        });
        count = next;
        write(0, children, n, links);
    }

    /** {@code wideNodes}: from {@link #countWideNodes}, so the array is allocated once at its final size. */
    void allocate(int wideNodes) {
        nodes = new float[BVH.FIRST_NODE + NODE_STRIDE * wideNodes];
    }

    /**
     * How many wide nodes {@link #collapse} writes for binary interior node {@code binary}: the same choices
     * without the writes (a few milliseconds for a million primitives, against allocating and copying an array
     * sized for the worst case).
     */
    int countWideNodes(int binary) {
        int[] children = new int[WIDTH];
        int n = open(binary, children);
        int total = 1;
        for (int c = 0; c < n; c++) {
            if (!b.isLeaf(children[c])) total += countWideNodes(children[c]);
        }
        return total;
    }

    /**
     * Fills {@code children} with the binary nodes that become the wide children of binary interior node
     * {@code binary}, in order; returns how many.
     */
    int open(int binary, int[] children) {
        if (leaves[binary] > greedyAbove) return openGreedily(binary, children);
        int first = ownSplit[binary];
        int n = expand(binary + 1, first, children, 0);
        return expand(b.data[2 * binary], WIDTH - first, children, n);
    }

    /** Appends the binary nodes that the optimal collapse gives {@code node}'s subtree in {@code slots} slots. */
    private int expand(int node, int slots, int[] children, int n) {
        int first = b.isLeaf(node) ? 0 : split[WIDTH * node + slots - 1];
        if (first == 0) {
            children[n] = node;
            return n + 1;
        }
        n = expand(node + 1, first, children, n);
        return expand(b.data[2 * node], slots - first, children, n);
    }

    /** {@link #open} above {@link #GREEDY_ABOVE} leaves: the interior child with the most work is opened first. */
    private int openGreedily(int binary, int[] children) {
        int n = 0;
        children[n++] = binary + 1;
        children[n++] = b.data[2 * binary];
        while (n < WIDTH) {
            int widest = -1;
            double widestWeight = -1;
            for (int i = 0; i < n; i++) {
                double weight = work[children[i]]; // -1 for a leaf: never opened
                if (weight > widestWeight) {
                    widestWeight = weight;
                    widest = i;
                }
            }
            if (widest < 0) break;
            int opened = children[widest];
            System.arraycopy(children, widest + 1, children, widest + 2, n - widest - 1);
            children[widest] = opened + 1;
            children[widest + 1] = b.data[2 * opened];
            n++;
        }
        return n;
    }

    /**
     * Lists in {@code roots} (from {@code n} on) the largest subtrees under binary node {@code binary} that the optimal
     * collapse takes; returns the new count.
     */
    private int optimalRoots(int binary, int[] roots, int n) {
        if (b.isLeaf(binary)) return n;
        if (leaves[binary] <= greedyAbove) {
            roots[n] = binary;
            return n + 1;
        }
        n = optimalRoots(binary + 1, roots, n);
        return optimalRoots(b.data[2 * binary], roots, n);
    }

    /**
     * Plans the optimal collapse of the subtree of {@code root}, its nodes bottom-up (they occupy the indices from
     * {@code root} on, 2 leaves - 1 of them). For each interior node and slot count j, the least area of the wide
     * nodes inside its subtree: taking one slot, the node is a wide node whose eight slots its children's subtrees
     * share as is cheapest, at the cost of its own area; taking j > 1, its children's subtrees may instead share the
     * j slots. A subtree never needs more slots than it has leaves (then it has no wide node), so only those splits
     * are tried: the same least areas for a fraction of the work near the leaves, where most nodes are. Ties keep the
     * fewer slots, then the first child's fewer.
     */
    private void planSubtree(int root, float[] cost) {
        int size = 2 * leaves[root] - 1;
        // cost[WIDTH (i - root) + j]: the least area inside node i's subtree in at most j + 1 slots (0 for a leaf).
        for (int i = root + size - 1; i >= root; i--) {
            if (b.isLeaf(i)) {
                Arrays.fill(cost, WIDTH * (i - root), WIDTH * (i - root + 1), 0f);
                continue;
            }
            int right = b.data[2 * i];
            int o = WIDTH * (i - root), l = WIDTH * (i + 1 - root), r = WIDTH * (right - root);
            int leftLeaves = leaves[i + 1], rightLeaves = leaves[right];
            // As a wide node: its first child's subtree takes k of the eight slots, the second's the rest.
            float inside = 0;
            int first = leftLeaves; // where all the leaves fit, each takes a slot
            if (leftLeaves + rightLeaves > WIDTH) {
                // Areas may be infinite or NaN (boxes beyond float's range): the first split stands if none is less.
                inside = Float.POSITIVE_INFINITY;
                first = Math.max(1, WIDTH - rightLeaves);
                for (int k = first; k <= Math.min(WIDTH - 1, leftLeaves); k++) {
                    float c = cost[l + k - 1] + cost[r + WIDTH - k - 1];
                    if (c < inside) {
                        inside = c;
                        first = k;
                    }
                }
            }
            ownSplit[i] = (byte) first;
            float own = (float) b.area(i) + inside;
            cost[o] = own;
            // A child takes at most seven of its parent's eight slots (its sibling takes one or more).
            int most = Math.min(WIDTH - 1, leftLeaves + rightLeaves);
            for (int j = 2; j <= most; j++) {
                float best = own;
                int choice = 0;
                for (int k = Math.max(1, j - rightLeaves); k <= Math.min(j - 1, leftLeaves); k++) {
                    float c = cost[l + k - 1] + cost[r + j - k - 1];
                    if (c < best) {
                        best = c;
                        choice = k;
                    }
                }
                cost[o + j - 1] = best;
                split[WIDTH * i + j - 1] = (byte) choice;
            }
            // More slots than leaves change nothing.
            for (int j = most + 1; j < WIDTH; j++) {
                cost[o + j - 1] = cost[o + most - 1];
                split[WIDTH * i + j - 1] = split[WIDTH * i + most - 1];
            }
        }
    }

    /** The binary nodes that became the root's children, slot by slot (filled by the root's collapse). */
    private final int[] rootChildren = new int[WIDTH];

    private int rootChildCount;

    /**
     * The mask of the root's slots whose binary subtrees lie at or after binary node {@code first} in
     * depth-first order: for the root's second child, the slots holding only that child's primitives.
     */
    int slotsFrom(int first) {
        int mask = 0;
        for (int c = 0; c < rootChildCount; c++) if (rootChildren[c] >= first) mask |= 1 << c;
        return mask;
    }

    /** Writes the wide node that replaces binary interior node {@code binary}; returns its index. */
    int collapse(int binary) {
        int self = count++;
        int[] children = new int[WIDTH];
        int n = open(binary, children);
        int[] links = new int[n];
        for (int c = 0; c < n; c++) {
            links[c] = b.isLeaf(children[c]) ? b.data[2 * children[c]] : collapse(children[c]);
        }
        write(self, children, n, links);
        return self;
    }

    /** Writes wide node {@code self}: its {@code n} children's boxes, links (node or first primitive) and counts. */
    private void write(int self, int[] children, int n, int[] links) {
        if (self == 0) {
            System.arraycopy(children, 0, rootChildren, 0, n);
            rootChildCount = n;
        }
        int o = BVH.nodeOffset(self);
        for (int c = 0; c < WIDTH; c++) {
            if (c >= n) {
                // An empty box: every slab test misses it (its near distance is +inf or NaN).
                for (int a = 0; a < 3; a++) {
                    nodes[o + MIN_X + WIDTH * a + c] = Float.POSITIVE_INFINITY;
                    nodes[o + MAX_X + WIDTH * a + c] = Float.NEGATIVE_INFINITY;
                }
                continue;
            }
            int child = children[c];
            for (int a = 0; a < 3; a++) {
                nodes[o + MIN_X + WIDTH * a + c] = b.bounds[6 * child + a];
                nodes[o + MAX_X + WIDTH * a + c] = b.bounds[6 * child + 3 + a];
            }
            boolean leaf = b.isLeaf(child);
            nodes[o + LINK + c] = Float.intBitsToFloat(links[c]);
            nodes[o + COUNT + c] = Float.intBitsToFloat(leaf ? b.data[2 * child + 1] : 0);
        }
    }
}
