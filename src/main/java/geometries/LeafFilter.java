package geometries;

import primitives.Ray;

/**
 * The first step of the watertight triangle test for the triangles of a BVH leaf at once: which of them the ray
 * does not pass outside of. A leaf of up to {@link #LANES} primitives is tested in one call from the leaf's lanes
 * ({@link CompiledPrimitives#filtersLeaves}), and only the candidates it returns go through
 * {@link WatertightTriangle#intersect}, in order, which decides them as before. Each lane computes the scalar test's
 * edge functions with the same IEEE operations in the same order, so a triangle is a candidate exactly when the
 * scalar test passes its edge and determinant checks: the filter never drops a hit, and the answers stay bit for bit
 * those of the scalar search. A query then pays one branch per leaf where it paid one per triangle.
 *
 * <p>Only on the JDK's incubating Vector API ({@link #SELECTED} is null without it): written in scalar code it would
 * be the scalar test's own first half.
 */
abstract class LeafFilter {
    /** Primitives a leaf may hold to be filtered in one call: four doubles, one 256-bit vector. */
    static final int LANES = 4;

    /**
     * Triangles a mesh must have for its leaves to be filled and filtered. A tessellated surface sends a ray through
     * many small leaves, each test an unpredictable branch, and there the filter paid (icospheres of 1,280 and 82k
     * triangles, heightfields of 2,178 to 1M: 1.07-1.36x); the street's meshes, boxes and panels of at most 672
     * large triangles among spheres and polygons, measured 0.85-0.93x filled and filtered (its rays are coherent,
     * and a split culls what a filled leaf tests).
     */
    static final int MIN_MESH = 1024;

    /** The filter this JVM runs, or null where the Vector API is absent (or the CPU has no 256-bit vectors). */
    static final LeafFilter SELECTED =
            VectorKernels.select(LeafFilter.class, "geometries.VectorLeafFilter", () -> null);

    /**
     * The candidates among the {@code count} primitives of the leaf whose lanes start at {@code o} of {@code lanes}:
     * bit i for the leaf's i-th primitive, set where it is a triangle that the ray does not pass outside of (edge
     * functions of one sign, determinant not zero) or is not a triangle. Bits from {@code count} on are undefined.
     */
    abstract int candidates(double[] lanes, int o, int count, Ray ray);
}
