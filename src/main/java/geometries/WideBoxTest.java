package geometries;

/**
 * The slab test of the {@link BVH#WIDTH} child boxes of a BVH node, the traversal's inner kernel, in float
 * arithmetic made conservative by {@link RaySlabs}. Two implementations give bit-identical answers: a scalar one,
 * and one on the JDK's incubating Vector API that tests the eight boxes in the eight lanes of a 256-bit vector
 * (AVX2). The vectorized one is chosen at startup when the JVM was started with
 * {@code --add-modules jdk.incubator.vector}; without the flag the library runs the scalar one.
 *
 * <p>For each child box the test finds where the ray enters and leaves it within {@code (tMin, tMax)}: the ray's
 * direction signs say which plane of each slab is entered first, the near distance is the largest entering one
 * and the far distance the smallest leaving one, each slab distance one fused multiply-add, and both ends widened
 * by {@link RaySlabs#SLACK} of their magnitude.
 */
abstract class WideBoxTest {
    /**
     * The kernel this JVM runs: vectorized if the Vector API module is present and the CPU has 256-bit vectors,
     * scalar otherwise.
     */
    static final WideBoxTest SELECTED = select();

    /** The entry distance of a missed box. */
    static final float MISS = Float.POSITIVE_INFINITY;

    /**
     * Tests the child boxes of the node at offset {@code o} of {@code nodes}: writes where the ray enters each within
     * {@code (tMin, tMax)}, or {@link #MISS}, to {@code entries[0..WIDTH)} and returns the mask of the children hit
     * (bit c for child c).
     *
     * @param tMin the query's start rounded down ({@link RaySlabs#below})
     * @param tMax the query's end rounded up ({@link RaySlabs#above})
     */
    abstract int test(float[] nodes, int o, RaySlabs ray, float tMin, float tMax, float[] entries);

    /** A short name for reports: "vector" or "scalar". */
    abstract String name();

    private static WideBoxTest select() {
        return VectorKernels.select(WideBoxTest.class, "geometries.VectorWideBoxTest", ScalarWideBoxTest::new);
    }

    /**
     * The double slab test for rays the float form cannot hold ({@link RaySlabs#floatSafe} false): zero or
     * subnormal direction components, whose slab distances may be {@code 0 * inf = NaN} when the ray lies in a
     * slab's plane (comparisons ignore the NaN there), or extreme magnitudes. Rare, so both implementations share it.
     */
    static int testInDouble(float[] nodes, int o, RaySlabs ray, float tMin, float tMax, float[] entries) {
        int mask = 0;
        for (int c = 0; c < BVH.WIDTH; c++) {
            double e = entryInDouble(nodes, o + c, ray, tMin, tMax);
            entries[c] = e < BoundingBox.MISS ? FloatBoxes.floatBelow(e) : MISS;
            if (e < BoundingBox.MISS) mask |= 1 << c;
        }
        return mask;
    }

    private static double entryInDouble(float[] nodes, int o, RaySlabs slabs, double tMin, double tMax) {
        primitives.Ray ray = slabs.ray;
        int sx = slabs.flipX, sy = slabs.flipY, sz = slabs.flipZ;
        double nx = (nodes[o + BVH.MIN_X + sx] - ray.ox()) * ray.invDx();
        double fx = (nodes[o + BVH.MAX_X - sx] - ray.ox()) * ray.invDx();
        double ny = (nodes[o + BVH.MIN_Y + sy] - ray.oy()) * ray.invDy();
        double fy = (nodes[o + BVH.MAX_Y - sy] - ray.oy()) * ray.invDy();
        double nz = (nodes[o + BVH.MIN_Z + sz] - ray.oz()) * ray.invDz();
        double fz = (nodes[o + BVH.MAX_Z - sz] - ray.oz()) * ray.invDz();
        // "nx > near" is false for NaN, so a NaN slab leaves the interval unchanged.
        double near = tMin, far = tMax;
        if (nx > near) near = nx;
        if (ny > near) near = ny;
        if (nz > near) near = nz;
        if (fx < far) far = fx;
        if (fy < far) far = fy;
        if (fz < far) far = fz;
        near -= Math.abs(near) * BoundingBox.SLAB_SLACK;
        far += Math.abs(far) * BoundingBox.SLAB_SLACK;
        return near <= far ? near : BoundingBox.MISS;
    }
}
