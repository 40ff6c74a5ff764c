package geometries;

import static geometries.BVH.COUNT;
import static geometries.BVH.LINK;
import static geometries.BVH.MAX_X;
import static geometries.BVH.MIN_X;
import static geometries.BVH.NODE_STRIDE;
import static geometries.BVH.WIDTH;

/**
 * Collapses a {@link BvhBuilder}'s binary tree into the wide nodes of a {@link BVH}, written depth-first: a wide node
 * starts from a binary node's two children and repeatedly opens the interior child with the most work below it (its
 * box's surface area times its primitives) until it has {@link BVH#WIDTH} children or only leaves.
 */
final class WideCollapser {
    private final BvhBuilder b;
    /**
     * What opening each binary node is worth: its box's surface area times its primitives, the SAH's estimate of
     * the work below it. Area alone (Embree's choice) spends root slots on the few huge, far objects of a scene
     * such as the street's moon and clouds, and leaves the street itself for the next level.
     */
    private final double[] work;

    float[] nodes;
    int count;

    WideCollapser(BvhBuilder b) {
        this.b = b;
        work = b.workBelow();
    }

    /** A collapser writing into {@code whole}'s nodes from wide node {@code first} on (a subtree of the root). */
    private WideCollapser(WideCollapser whole, int first) {
        b = whole.b;
        work = whole.work;
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
            if (!isLeaf(b, children[c])) sizes[c] = countWideNodes(children[c]);
        });
        int[] links = new int[n];
        int next = 1;
        for (int c = 0; c < n; c++) {
            links[c] = isLeaf(b, children[c]) ? b.data[2 * children[c]] : next;
            next += sizes[c];
        }
        allocate(next);
        BuildPool.forEach(n, true, c -> {
            if (!isLeaf(b, children[c])) new WideCollapser(this, links[c]).collapse(children[c]);
        });
        count = next;
        write(0, children, n, links);
    }

    /** {@code wideNodes}: from {@link #countWideNodes}, so the array is allocated once at its final size. */
    void allocate(int wideNodes) {
        nodes = new float[NODE_STRIDE * wideNodes];
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
            if (!isLeaf(b, children[c])) total += countWideNodes(children[c]);
        }
        return total;
    }

    /**
     * Fills {@code children} with the binary nodes that become the wide children of binary interior node
     * {@code binary}, in order; returns how many.
     */
    int open(int binary, int[] children) {
        int n = 0;
        children[n++] = binary + 1;
        children[n++] = b.data[2 * binary];
        while (n < WIDTH) {
            // Open the interior child with the most work below it.
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
            links[c] = isLeaf(b, children[c]) ? b.data[2 * children[c]] : collapse(children[c]);
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
        int o = NODE_STRIDE * self;
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
            boolean leaf = isLeaf(b, child);
            nodes[o + LINK + c] = Float.intBitsToFloat(links[c]);
            nodes[o + COUNT + c] = Float.intBitsToFloat(leaf ? b.data[2 * child + 1] : 0);
        }
    }

    private static boolean isLeaf(BvhBuilder b, int binary) {
        return b.data[2 * binary + 1] > 0;
    }
}
