package geometries;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorShape;
import jdk.incubator.vector.VectorSpecies;

/**
 * {@link WideBoxTest} on the JDK's incubating Vector API: the eight child boxes of a node in the eight lanes of a
 * 256-bit vector of floats, three fused multiply-adds per side of the slab. Every lane computes what
 * {@link ScalarWideBoxTest} computes for its box (the same IEEE operations in the same order), so the masks and
 * the entry distances are identical. Loaded only when the JVM runs with {@code --add-modules jdk.incubator.vector}.
 */
final class VectorWideBoxTest extends WideBoxTest {
    private static final VectorSpecies<Float> FLOATS =
            VectorSpecies.of(float.class, VectorShape.forBitSize(Float.SIZE * BVH.WIDTH));
    private static final VectorSpecies<Integer> INTS =
            VectorSpecies.of(int.class, VectorShape.forBitSize(Integer.SIZE * BVH.WIDTH));
    /** Bit c in lane c: blended by the hit mask and OR-ed together, it gives the mask as an int. */
    private static final IntVector LANE_BITS = IntVector.broadcast(INTS, 1)
            .lanewise(VectorOperators.LSHL, IntVector.zero(INTS).addIndex(1));

    private static final IntVector NO_BITS = IntVector.zero(INTS);
    private static final FloatVector MISSES = FloatVector.broadcast(FLOATS, MISS);
    private static final FloatVector POSITIVE_SLACK = FloatVector.broadcast(FLOATS, RaySlabs.SLACK);
    private static final FloatVector NEGATIVE_SLACK = FloatVector.broadcast(FLOATS, -RaySlabs.SLACK);

    /**
     * Refuses (and {@link WideBoxTest} falls back to the scalar kernel) where the CPU has no 256-bit vectors
     * (SSE-only x86, 128-bit NEON): there the JIT would not compile the vector operations to instructions, and
     * the Vector API's Java fallback is far slower than scalar code.
     */
    VectorWideBoxTest() {
        if (BVH.WIDTH != FLOATS.length()) throw new IllegalStateException("one lane per child box");
        if (FloatVector.SPECIES_PREFERRED.vectorBitSize() < 256) {
            throw new UnsupportedOperationException("no 256-bit vectors on this CPU");
        }
    }

    @Override
    int test(float[] nodes, int o, RaySlabs r, float tMin, float tMax, float[] entries) {
        if (!r.floatSafe) return testInDouble(nodes, o, r, tMin, tMax, entries);
        FloatVector near = max(
                max(
                        slab(nodes, o + BVH.MIN_X + r.flipX, r.invX, r.nearX),
                        slab(nodes, o + BVH.MIN_Y + r.flipY, r.invY, r.nearY)),
                slab(nodes, o + BVH.MIN_Z + r.flipZ, r.invZ, r.nearZ));
        FloatVector far = min(
                min(
                        slab(nodes, o + BVH.MAX_X - r.flipX, r.invX, r.farX),
                        slab(nodes, o + BVH.MAX_Y - r.flipY, r.invY, r.farY)),
                slab(nodes, o + BVH.MAX_Z - r.flipZ, r.invZ, r.farZ));
        near = near.abs().fma(NEGATIVE_SLACK, near);
        far = far.abs().fma(POSITIVE_SLACK, far);
        VectorMask<Float> hit = near.compare(VectorOperators.LE, far)
                .and(near.compare(VectorOperators.LE, tMax))
                .and(far.compare(VectorOperators.GE, tMin));
        MISSES.blend(near, hit).intoArray(entries, 0);
        // VectorMask.toLong is not an intrinsic on JDK 17 (measured 20% slower on the street's shadow rays); a
        // blend and an OR across the lanes are.
        return NO_BITS.blend(LANE_BITS, hit.cast(INTS)).reduceLanes(VectorOperators.OR);
    }

    /**
     * The larger of each pair of lanes by one comparison and one blend. Lanewise MAX has Math.max semantics (NaN
     * wins, -0 below +0), more instructions on the chain every node visit waits on. Here no operand is NaN
     * ({@link RaySlabs#floatSafe}: finite normal reciprocals and offsets, bounds finite or infinite), and where
     * the two differ, for zeros of opposite sign, the scalar kernel makes the same choice.
     */
    private static FloatVector max(FloatVector a, FloatVector b) {
        return a.blend(b, a.compare(VectorOperators.LT, b));
    }

    /** The smaller of each pair of lanes; see {@link #max}. */
    private static FloatVector min(FloatVector a, FloatVector b) {
        return a.blend(b, b.compare(VectorOperators.LT, a));
    }

    /** Distances along the ray to the eight planes {@code nodes[i..i+8)} of one axis. */
    private static FloatVector slab(float[] nodes, int i, float reciprocal, float offset) {
        return FloatVector.fromArray(FLOATS, nodes, i).fma(reciprocal, -offset);
    }

    @Override
    String name() {
        return "vector";
    }
}
