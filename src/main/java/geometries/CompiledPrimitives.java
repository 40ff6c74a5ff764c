package geometries;

import primitives.Double3;
import primitives.Ray;

/**
 * The primitives of an {@link Accelerator} laid out flat in BVH leaf order (insertion order without a BVH), as the
 * traversals read them: a triangle's nine coordinates in one array, tested in place; other bounded shapes called
 * through {@link Intersectable}; unbounded geometry apart, tested beside the tree. Also how a primitive is classed
 * for shadow rays ({@link #mayTransmit(Intersectable)}, {@link #isClear}).
 */
final class CompiledPrimitives {
    /** The shared-edge entry of {@link #info} for a primitive that is not a triangle. */
    static final int OBJECT = -1;
    /** Primitives from which the layout runs in parallel. */
    private static final int PARALLEL_LAYOUT = 1 << 16;

    final int boundedCount;
    /** Per bounded primitive in search order: 9 coordinates if it is a triangle. */
    final double[] triangles;

    /** Ints per primitive in {@link #info}. */
    static final int INFO = 4;
    /** Where in a primitive's {@link #info} its original (insertion) index is: the deterministic tie-break. */
    static final int INDEX = 0;
    /** Where its triangle's shared-edge flags are, or {@link #OBJECT} for other shapes. */
    static final int EDGES = 1;
    /** Where its triangle's owner is: a slot of {@link #geometries}. */
    static final int OWNER = 2;
    /** Where its triangle's part index within the owner is. */
    static final int PART = 3;

    /**
     * {@link #INFO} ints per primitive: index, edges, owner, part. One record, so that the owner and part of a query's
     * final hit come from the cache line its test already read (in separate arrays they were two cache misses per
     * query on large meshes: 5% of an incoherent ray's time in {@code perf}).
     */
    final int[] info;
    /** The geometries that own triangles, each once, indexed by the {@link #OWNER} of {@link #info}. */
    final Geometry[] geometries;
    /** Non-triangle bounded primitives (null where the primitive is a triangle). */
    final Intersectable[] objects;
    /** Whether a primitive may let light through (then shadow rays must look past it). */
    final boolean[] mayTransmit;
    /**
     * Whether a primitive is clear (a Geometry whose kT is exactly 1 in every channel): it changes no transmittance
     * (a product times 1 is exact), so shadow queries skip it; the lamp globes of the street are such.
     */
    final boolean[] clear;

    final Intersectable[] unbounded;
    final boolean[] unboundedMayTransmit, unboundedClear;
    /**
     * Whether the traversals search the tree: not over a single bounded primitive, where a query would set up the
     * root's slabs only to reach the one test that brute force makes directly (6-12% of a warm render of the POV-Ray
     * comparison scene, a plane and a sphere, in three alternated pairs).
     */
    final boolean searchesTree;

    /**
     * Whether some leaves are filled ({@link FilledLeaves}: at most {@link LeafFilter#LANES} triangles of large meshes)
     * and laid out lane by lane in {@link #triangles} for the {@link LeafFilter}: the leaf at {@code link} with {@code
     * count} triangles has its i-th one's coordinate j of vertex v at {@code 9 link + count (3 v + j) + i}, in the
     * same space as the nine per triangle elsewhere. Their {@link #EDGES} entries say so ({@link #FILLED}).
     */
    final boolean filtersLeaves;

    /**
     * The filter of the filled leaves, or null where there are none: read only then, since its class loads the Vector
     * API, tens of milliseconds in a new JVM that a scene of small meshes and shapes need not wait for.
     */
    final LeafFilter leafFilter;

    /**
     * The flag, in a triangle's {@link #EDGES} entry, of a triangle of a filled leaf; above it its lane (2 bits) and
     * its leaf's count (3 bits), below it the shared-edge flags. So a filled triangle's entry is at least this, another
     * triangle's at most {@link WatertightTriangle#ALL_EDGES_SHARED}, an object's {@link #OBJECT}.
     */
    static final int FILLED = 8;

    private static final int LANE_SHIFT = 4, COUNT_SHIFT = 6;

    /** Whether {@code edges}, a primitive's {@link #EDGES} entry, is a filled leaf's triangle's. */
    static boolean isFilled(int edges) {
        return edges >= FILLED;
    }

    /** The lane, in its filled leaf, of the triangle whose {@link #EDGES} entry is {@code edges}. */
    static int lane(int edges) {
        return (edges >> LANE_SHIFT) & 3;
    }

    /** The count of the filled leaf of the triangle whose {@link #EDGES} entry is {@code edges}. */
    static int leafCount(int edges) {
        return edges >> COUNT_SHIFT;
    }

    /**
     * Lays out the primitives {@code c} collected in the leaf order of {@code bvh}, or in insertion order when
     * {@code bvh} is null; the leaves {@code filled} takes lane by lane.
     */
    CompiledPrimitives(PrimitiveCollector c, BVH bvh, FilledLeaves filled) {
        int n = c.count;
        boundedCount = n;
        searchesTree = bvh != null && n > 1;
        filtersLeaves = searchesTree && filled.size() > 0;
        leafFilter = filtersLeaves ? LeafFilter.SELECTED : null;
        // A vector's padding after the last leaf: the filter's loads of four lanes read past a leaf of fewer.
        triangles = new double[9 * n + (filtersLeaves ? LeafFilter.LANES : 0)];
        info = new int[INFO * n];
        geometries = c.ownerTable();
        objects = new Intersectable[n];
        mayTransmit = new boolean[n];
        clear = new boolean[n];
        int[] position = bvh == null ? null : positions(bvh.order);
        // Each primitive is written to its own position alone, so large meshes lay out on all cores; in the order they
        // were collected, so that reading a mesh's vertices and the collector's arrays runs through memory in order
        // and only the writes land where the leaves put them.
        BuildPool.forEach(n, n >= PARALLEL_LAYOUT, i -> layOut(c, i, position == null ? i : position[i]));
        if (filtersLeaves) fillLeaves(bvh, filled);
        unbounded = c.unbounded.toArray(new Intersectable[0]);
        unboundedMayTransmit = new boolean[unbounded.length];
        unboundedClear = new boolean[unbounded.length];
        for (int j = 0; j < unbounded.length; j++) {
            unboundedMayTransmit[j] = mayTransmit(unbounded[j]);
            unboundedClear[j] = isClear(unbounded[j]);
        }
    }

    /**
     * Where each primitive goes: the inverse of the leaf order {@code order}, a permutation, so each position is
     * written once and large ones fill on all cores.
     */
    private static int[] positions(int[] order) {
        int[] position = new int[order.length];
        BuildPool.forEachChunk(order.length, PARALLEL_LAYOUT, true, (chunk, from, to) -> {
            for (int k = from; k < to; k++) position[order[k]] = k;
        });
        return position;
    }

    /**
     * Writes primitive {@code i} into the flat arrays at position {@code k} of the leaf order. The arrays start zeroed,
     * and only values other than null and false are written: position {@code k} is far from {@code k - 1}'s, so each
     * array written is a cache line fetched, and a mesh's triangles have no object and are mostly opaque and not clear.
     */
    private void layOut(PrimitiveCollector c, int i, int k) {
        int r = INFO * k;
        info[r + INDEX] = i;
        Intersectable object = c.objects[i];
        if (c.mayTransmit[i]) mayTransmit[k] = true;
        if (c.clear[i]) clear[k] = true;
        if (object == null) {
            c.copyTriangle(i, triangles, 9 * k);
            info[r + EDGES] = c.shared[i];
            info[r + OWNER] = c.owners[i];
            info[r + PART] = c.parts[i];
        } else {
            objects[k] = object;
            info[r + EDGES] = OBJECT;
            info[r + OWNER] = -1;
        }
    }

    /**
     * Lays the leaves of {@code bvh} that {@code filled} takes out lane by lane, in place, and flags their triangles;
     * node by node, on all cores for large trees (each leaf is written by one task).
     */
    private void fillLeaves(BVH bvh, FilledLeaves filled) {
        float[] nodes = bvh.nodes;
        int nodeCount = (nodes.length - BVH.FIRST_NODE) / BVH.NODE_STRIDE;
        if (bvh.rootCount > 0) fillLeaf(bvh, filled, bvh.rootLink, bvh.rootCount, new double[9 * LeafFilter.LANES]);
        BuildPool.forEachChunk(nodeCount, PARALLEL_LAYOUT / BVH.WIDTH, true, (chunk, from, to) -> {
            double[] copy = new double[9 * LeafFilter.LANES];
            for (int node = from; node < to; node++) {
                int o = BVH.nodeOffset(node);
                for (int c = 0; c < BVH.WIDTH; c++) {
                    int count = Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
                    int link = Float.floatToRawIntBits(nodes[o + BVH.LINK + c]);
                    if (count > 0) fillLeaf(bvh, filled, link, count, copy);
                }
            }
        });
    }

    /**
     * Lays out the leaf of {@code count} at {@code link} lane by lane if {@code filled} takes it ({@code copy}: room).
     */
    private void fillLeaf(BVH bvh, FilledLeaves filled, int link, int count, double[] copy) {
        if (count > LeafFilter.LANES || !filled.fill(bvh.order, link, link + count)) return;
        System.arraycopy(triangles, 9 * link, copy, 0, 9 * count);
        toLanes(copy, 0, triangles, 9 * link, count);
        for (int i = 0; i < count; i++)
            info[INFO * (link + i) + EDGES] |= FILLED | i << LANE_SHIFT | count << COUNT_SHIFT;
    }

    /**
     * {@link WatertightTriangle#intersect} for triangle {@code lane} of the filled leaf of {@code count} at {@code
     * link}, whose {@link #EDGES} entry is {@code edges} (its flags above the shared edges are masked off here).
     */
    static boolean intersectFilled(
            double[] triangles,
            int link,
            int lane,
            int count,
            int edges,
            Ray ray,
            double tMin,
            double tMax,
            HitRecord hit) {
        int a = 9 * link + lane;
        return WatertightTriangle.intersect(
                triangles,
                a,
                a + 3 * count,
                a + 6 * count,
                count,
                edges & WatertightTriangle.ALL_EDGES_SHARED,
                ray,
                tMin,
                tMax,
                hit);
    }

    /**
     * Writes {@code count} triangles, nine coordinates each from {@code source[from]} on, lane by lane to {@code
     * lanes[at]} on: coordinate j of the i-th at {@code at + count j + i}, the layout of a filled leaf.
     */
    static void toLanes(double[] source, int from, double[] lanes, int at, int count) {
        for (int i = 0; i < count; i++) {
            for (int j = 0; j < 9; j++) lanes[at + count * j + i] = source[from + 9 * i + j];
        }
    }

    /** Bytes of the flat arrays of the bounded primitives. */
    long bytes() {
        return 8L * triangles.length
                + 4L * info.length
                + 8L * (geometries.length + objects.length)
                + 2L * mayTransmit.length;
    }

    /** Whether any primitive may let light through. */
    boolean mayTransmit() {
        for (boolean b : mayTransmit) if (b) return true;
        for (boolean b : unboundedMayTransmit) if (b) return true;
        return false;
    }

    /** Whether {@code g} is clear: a Geometry whose kT is exactly 1 in every channel. */
    static boolean isClear(Intersectable g) {
        if (!(g instanceof Geometry geometry)) return false;
        Double3 kT = geometry.getMaterial().getKt();
        return kT.d1 == 1 && kT.d2 == 1 && kT.d3 == 1;
    }

    /** Whether {@code g} may let light through, so that shadow rays must look past it. */
    static boolean mayTransmit(Intersectable g) {
        if (g instanceof Instance instance) return instance.mayTransmit();
        // Non-Geometry members (user composites) may contain transparent surfaces: decide per hit.
        return !(g instanceof Geometry geometry) || geometry.getMaterial().isTransparent();
    }
}
