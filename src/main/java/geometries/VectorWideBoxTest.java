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
        this(MASK_TO_LONG);
    }

    /** A kernel that reads its masks with {@link VectorMask#toLong} or not (tests compare both on any JDK). */
    VectorWideBoxTest(boolean maskToLong) {
        this.maskToLong = maskToLong;
        if (BVH.WIDTH != FLOATS.length()) throw new IllegalStateException("one lane per child box");
        if (FloatVector.SPECIES_PREFERRED.vectorBitSize() < 256) {
            throw new UnsupportedOperationException("no 256-bit vectors on this CPU");
        }
    }

    /**
     * Written out in one method, on purpose: no vector crosses a call boundary, so nothing is boxed even where the
     * JIT declines to inline a helper (it did, "callee uses too much stack", and boxed about 19 bytes per ray).
     * Max and min are one comparison and one blend each: lanewise MAX has Math.max semantics (NaN wins, -0 below
     * +0), more instructions on the chain every node visit waits on; here no operand is NaN ({@link
     * RaySlabs#floatSafe}: finite normal reciprocals and offsets, bounds finite or infinite), and where the two
     * differ, for zeros of opposite sign, the scalar kernel makes the same choice.
     */
    @Override
    int test(float[] nodes, int o, RaySlabs r, float tMin, float tMax, float[] entries) {
        if (!r.floatSafe) return testInDouble(nodes, o, r, tMin, tMax, entries);
        FloatVector nx =
                FloatVector.fromArray(FLOATS, nodes, o + BVH.MIN_X + r.flipX).fma(r.invX, -r.nearX);
        FloatVector ny =
                FloatVector.fromArray(FLOATS, nodes, o + BVH.MIN_Y + r.flipY).fma(r.invY, -r.nearY);
        FloatVector nz =
                FloatVector.fromArray(FLOATS, nodes, o + BVH.MIN_Z + r.flipZ).fma(r.invZ, -r.nearZ);
        FloatVector fx =
                FloatVector.fromArray(FLOATS, nodes, o + BVH.MAX_X - r.flipX).fma(r.invX, -r.farX);
        FloatVector fy =
                FloatVector.fromArray(FLOATS, nodes, o + BVH.MAX_Y - r.flipY).fma(r.invY, -r.farY);
        FloatVector fz =
                FloatVector.fromArray(FLOATS, nodes, o + BVH.MAX_Z - r.flipZ).fma(r.invZ, -r.farZ);
        FloatVector near = nx.blend(ny, nx.compare(VectorOperators.LT, ny));
        near = near.blend(nz, near.compare(VectorOperators.LT, nz));
        FloatVector far = fx.blend(fy, fy.compare(VectorOperators.LT, fx));
        far = far.blend(fz, fz.compare(VectorOperators.LT, far));
        near = near.abs().fma(NEGATIVE_SLACK, near);
        far = far.abs().fma(POSITIVE_SLACK, far);
        VectorMask<Float> hit = near.compare(VectorOperators.LE, far)
                .and(near.compare(VectorOperators.LE, tMax))
                .and(far.compare(VectorOperators.GE, tMin));
        MISSES.blend(near, hit).intoArray(entries, 0);
        return mask(hit, maskToLong);
    }

    /**
     * Whether the mask is read with {@link VectorMask#toLong}: an intrinsic on JDK 25 (BvhBenchmark on Temurin 25,
     * four pairs alternated against the OR: mostly 1.02-1.28x), a slow path on JDK 17 (a traversal harness: 0.72x
     * coherent, 0.89x incoherent; earlier 5-6% slower on the street render), where a blend and an OR across the lanes
     * are intrinsics. JDKs 18 to 24 were not measured and keep the OR.
     */
    static final boolean MASK_TO_LONG = Runtime.version().feature() >= 25;

    private final boolean maskToLong;

    /** The hit mask as an int, bit c for lane c, either way; both give the same bits. */
    private static int mask(VectorMask<Float> hit, boolean toLong) {
        return toLong
                ? (int) hit.toLong()
                : NO_BITS.blend(LANE_BITS, hit.cast(INTS)).reduceLanes(VectorOperators.OR);
    }

    @Override
    String name() {
        return "vector";
    }
}
