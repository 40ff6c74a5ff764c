package geometries;

import primitives.Ray;

/**
 * A ray's constants for the float slab test of {@link WideBoxTest}, computed once per query: the reciprocal
 * direction in float, and the origin's offsets {@code o * (1/d)} per axis rounded so that float arithmetic never
 * misses a box that exact arithmetic hits.
 *
 * <p>A slab distance is {@code t = b/d - o/d}, computed as one fused multiply-add {@code fma(b, inv, -offset)}.
 * Rounding the reciprocal to float errs by {@code 2^-24 |b inv|} at most, which is below
 * {@code 2^-24 (|t| + |o inv|)}; the offset subtracted from near planes is therefore rounded up by
 * {@code 2^-21 |o inv|} and the one subtracted from far planes down by as much, which leaves an error relative to
 * {@code |t|} alone, about {@code 2^-23 |t|}. The test then widens every near distance down and every far
 * distance up by {@link #SLACK} of its magnitude (four times that), and the query interval outward by a float
 * step. So the float answer is conservative like the double one of {@link BoundingBox#entry}
 * (docs/ROBUSTNESS.md): a box may be entered slightly early, never missed.
 *
 * <p>Where the float form cannot hold the ray (a zero, subnormal or huge direction component, an offset beyond
 * float range) {@link #floatSafe} is false and the test falls back to the double slab test.
 */
final class RaySlabs {
    /** Relative widening of float slab distances: {@code 2^-21}, four times their worst rounding error. */
    static final float SLACK = 0x1p-21f;
    /** Relative rounding of the origin offsets, see the class comment. */
    private static final double OFFSET_SLACK = 0x1p-21;
    /** An absolute slack on the offsets, far below any distance that matters, above float's rounding there. */
    private static final double TINY = 0x1p-140;

    /** The reciprocal direction in float. */
    float invX, invY, invZ;
    /** {@code o * inv} per axis, rounded up: subtracted from the near planes. */
    float nearX, nearY, nearZ;
    /** {@code o * inv} per axis, rounded down: subtracted from the far planes. */
    float farX, farY, farZ;
    /** Offsets that pick each axis's near plane in a node ({@code 0} or {@code BVH.MAX_X - BVH.MIN_X}). */
    int flipX, flipY, flipZ;
    /** Whether the float test applies to this ray. */
    boolean floatSafe;
    /** The ray, for the double fallback. */
    Ray ray;

    /** Sets the constants for {@code ray}; allocation-free, once per query. */
    void set(Ray ray) {
        this.ray = ray;
        double ix = ray.invDx(), iy = ray.invDy(), iz = ray.invDz();
        int s = BoundingBox.directionSigns(ray);
        boolean finite = (s & BoundingBox.FINITE_RECIPROCALS) != 0;
        flipX = (s & 1) * BVH.MAX_X;
        flipY = (s >> 1 & 1) * BVH.MAX_X;
        flipZ = (s >> 2 & 1) * BVH.MAX_X;
        double ox = ray.ox() * ix, oy = ray.oy() * iy, oz = ray.oz() * iz;
        invX = (float) ix;
        invY = (float) iy;
        invZ = (float) iz;
        // Rounding to the nearest float moves an offset by 2^-24 of it at most: the slack of 2^-21 leaves more than
        // the 2^-22 needed, and the tiny absolute term keeps offsets below float's normal range on the safe side.
        double sx = Math.abs(ox) * OFFSET_SLACK + TINY, sy = Math.abs(oy) * OFFSET_SLACK + TINY;
        double sz = Math.abs(oz) * OFFSET_SLACK + TINY;
        nearX = (float) (ox + sx);
        nearY = (float) (oy + sy);
        nearZ = (float) (oz + sz);
        farX = (float) (ox - sx);
        farY = (float) (oy - sy);
        farZ = (float) (oz - sz);
        // Reciprocals of normal magnitude, so products with infinite bounds are infinite rather than NaN, and every
        // constant finite (checked on the sum of magnitudes, which is finite only if each is).
        float smallest = Math.min(Math.abs(invX), Math.min(Math.abs(invY), Math.abs(invZ)));
        float sum = Math.abs(invX)
                + Math.abs(invY)
                + Math.abs(invZ)
                + Math.abs(nearX)
                + Math.abs(nearY)
                + Math.abs(nearZ)
                + Math.abs(farX)
                + Math.abs(farY)
                + Math.abs(farZ);
        floatSafe = finite & smallest >= Float.MIN_NORMAL & sum <= Float.MAX_VALUE;
    }

    /**
     * Makes these constants those of a "fat" ray, for which every box is widened by {@code r} on each side: a box's
     * near plane moves by {@code r} toward the ray's origin, its slab distance by {@code r |1/d|}, and so the offset
     * subtracted from near planes grows by that much (rounded up) and the one subtracted from far planes shrinks by
     * as much (rounded down). The caller widens {@code r} for the rounding of the float reciprocal.
     *
     * @param r the widening, at least 0
     * @return whether the float test still applies ({@link #floatSafe})
     */
    boolean widen(double r) {
        if (!floatSafe) return false;
        double sx = r * Math.abs(invX), sy = r * Math.abs(invY), sz = r * Math.abs(invZ);
        nearX = Math.nextUp((float) (nearX + sx));
        nearY = Math.nextUp((float) (nearY + sy));
        nearZ = Math.nextUp((float) (nearZ + sz));
        farX = Math.nextDown((float) (farX - sx));
        farY = Math.nextDown((float) (farY - sy));
        farZ = Math.nextDown((float) (farZ - sz));
        float sum =
                Math.abs(nearX) + Math.abs(nearY) + Math.abs(nearZ) + Math.abs(farX) + Math.abs(farY) + Math.abs(farZ);
        floatSafe = sum <= Float.MAX_VALUE;
        return floatSafe;
    }

    /** A float not above {@code tMin}, one step below its rounding (covers the underflow of tiny distances). */
    static float below(double tMin) {
        return Math.nextDown((float) tMin);
    }

    /** A float not below {@code tMax}, one step above its rounding. */
    static float above(double tMax) {
        return Math.nextUp((float) tMax);
    }
}
