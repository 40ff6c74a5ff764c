package geometries;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.LongVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import primitives.Ray;

/**
 * {@link WideBoxTest} on the JDK's incubating Vector API: the four child boxes of a node in the four lanes of a
 * 256-bit vector of doubles. Every lane computes what {@link ScalarWideBoxTest} computes for its box (the same
 * float-to-double conversions, the same IEEE operations in the same order), so the masks are identical and the
 * entry distances equal (bit for bit but for the sign of a zero, see {@link #max}). Loaded only when the JVM runs
 * with {@code --add-modules jdk.incubator.vector}.
 */
final class VectorWideBoxTest extends WideBoxTest {
    private static final VectorSpecies<Float> FLOATS = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> DOUBLES = DoubleVector.SPECIES_256;
    private static final VectorSpecies<Long> LONGS = LongVector.SPECIES_256;
    /** Bit c in lane c: blended by the hit mask and OR-ed together, it gives the mask as an int. */
    private static final LongVector LANE_BITS = LongVector.fromArray(LONGS, new long[] {1, 2, 4, 8}, 0);

    private static final LongVector NO_BITS = LongVector.zero(LONGS);
    private static final DoubleVector MISS = DoubleVector.broadcast(DOUBLES, BoundingBox.MISS);

    /**
     * Refuses (and {@link WideBoxTest} falls back to the scalar kernel) where the CPU has no 256-bit vectors
     * (SSE-only x86, 128-bit NEON): there the JIT would not compile the vector operations to instructions, and
     * the Vector API's Java fallback is far slower than scalar code.
     */
    VectorWideBoxTest() {
        if (BVH.WIDTH != DOUBLES.length()) throw new IllegalStateException("one lane per child box");
        if (DoubleVector.SPECIES_PREFERRED.vectorBitSize() < DOUBLES.vectorBitSize()) {
            throw new UnsupportedOperationException("no " + DOUBLES.vectorBitSize() + "-bit vectors on this CPU");
        }
    }

    @Override
    int test(float[] nodes, int o, Ray ray, int signs, double tMin, double tMax, double[] entries) {
        if ((signs & BoundingBox.FINITE_RECIPROCALS) == 0) {
            return testWithInfiniteReciprocals(nodes, o, ray, signs, tMin, tMax, entries);
        }
        int flipX = (signs & 1) * BVH.MAX_X, flipY = (signs >> 1 & 1) * BVH.MAX_X, flipZ = (signs >> 2 & 1) * BVH.MAX_X;
        DoubleVector near = max(
                max(
                        slab(nodes, o + BVH.MIN_X + flipX, ray.ox(), ray.invDx()),
                        slab(nodes, o + BVH.MIN_Y + flipY, ray.oy(), ray.invDy())),
                slab(nodes, o + BVH.MIN_Z + flipZ, ray.oz(), ray.invDz()));
        DoubleVector far = min(
                min(
                        slab(nodes, o + BVH.MAX_X - flipX, ray.ox(), ray.invDx()),
                        slab(nodes, o + BVH.MAX_Y - flipY, ray.oy(), ray.invDy())),
                slab(nodes, o + BVH.MAX_Z - flipZ, ray.oz(), ray.invDz()));
        near = near.sub(near.abs().mul(BoundingBox.SLAB_SLACK));
        far = far.add(far.abs().mul(BoundingBox.SLAB_SLACK));
        VectorMask<Double> hit = near.compare(VectorOperators.LE, far)
                .and(near.compare(VectorOperators.LE, tMax))
                .and(far.compare(VectorOperators.GE, tMin));
        MISS.blend(near, hit).intoArray(entries, 0);
        // VectorMask.toLong is not an intrinsic on JDK 17; a blend and an OR across the lanes are.
        return (int) NO_BITS.blend(LANE_BITS, hit.cast(LONGS)).reduceLanes(VectorOperators.OR);
    }

    /**
     * The larger of each pair of lanes by one comparison and one blend. Lanewise MAX has Math.max semantics (NaN
     * wins, -0 below +0), five instructions that lengthen the chain every node visit waits on. Here no operand is
     * NaN (reciprocals are finite, bounds finite or infinite, never an infinity minus itself), and where the two
     * differ, for zeros of opposite sign, no comparison of the traversal can tell.
     */
    private static DoubleVector max(DoubleVector a, DoubleVector b) {
        return a.blend(b, a.compare(VectorOperators.LT, b));
    }

    /** The smaller of each pair of lanes; see {@link #max}. */
    private static DoubleVector min(DoubleVector a, DoubleVector b) {
        return a.blend(b, b.compare(VectorOperators.LT, a));
    }

    /** Distances along the ray to the four planes {@code nodes[i..i+4)} of one axis. */
    private static DoubleVector slab(float[] nodes, int i, double origin, double reciprocal) {
        return ((DoubleVector) FloatVector.fromArray(FLOATS, nodes, i).convertShape(VectorOperators.F2D, DOUBLES, 0))
                .sub(origin)
                .mul(reciprocal);
    }

    @Override
    String name() {
        return "vector";
    }
}
