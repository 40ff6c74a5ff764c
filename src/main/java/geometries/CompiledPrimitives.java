package geometries;

import java.util.stream.IntStream;
import primitives.Double3;

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

    /**
     * Two ints per primitive, read together by every test: the original (insertion) index, which is the
     * deterministic tie-break, then a triangle's shared-edge flags or {@link #OBJECT} for other shapes.
     */
    final int[] info;
    /** The geometry owning each triangle and the part index within it; read once per query, for the final hit. */
    final Geometry[] owners;

    final int[] parts;
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
     * Lays out the primitives {@code c} collected in the leaf order of {@code bvh}, or in insertion order when
     * {@code bvh} is null.
     */
    CompiledPrimitives(PrimitiveCollector c, BVH bvh) {
        int n = c.count;
        boundedCount = n;
        searchesTree = bvh != null && n > 1;
        triangles = new double[9 * n];
        info = new int[2 * n];
        owners = new Geometry[n];
        parts = new int[n];
        objects = new Intersectable[n];
        mayTransmit = new boolean[n];
        clear = new boolean[n];
        int[] order = bvh == null ? null : bvh.order;
        // Each position is written from its own primitive alone, so large meshes lay out on all cores.
        IntStream positions = IntStream.range(0, n);
        (n >= PARALLEL_LAYOUT ? positions.parallel() : positions).forEach(k -> layOut(c, order, k));
        unbounded = c.unbounded.toArray(new Intersectable[0]);
        unboundedMayTransmit = new boolean[unbounded.length];
        unboundedClear = new boolean[unbounded.length];
        for (int j = 0; j < unbounded.length; j++) {
            unboundedMayTransmit[j] = mayTransmit(unbounded[j]);
            unboundedClear[j] = isClear(unbounded[j]);
        }
    }

    /** Writes the primitive at position {@code k} of the leaf order into the flat arrays. */
    private void layOut(PrimitiveCollector c, int[] order, int k) {
        int i = order == null ? k : order[k];
        info[2 * k] = i;
        objects[k] = c.objects[i];
        mayTransmit[k] = c.mayTransmit[i];
        clear[k] = c.clear[i];
        if (objects[k] == null) {
            System.arraycopy(c.triangles, 9 * i, triangles, 9 * k, 9);
            info[2 * k + 1] = c.shared[i];
            owners[k] = c.owners[i];
            parts[k] = c.parts[i];
        } else {
            info[2 * k + 1] = OBJECT;
        }
    }

    /** Bytes of the flat arrays of the bounded primitives. */
    long bytes() {
        return 8L * triangles.length
                + 4L * (info.length + parts.length)
                + 8L * (owners.length + objects.length)
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
