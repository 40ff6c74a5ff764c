package geometries;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.LongVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import primitives.Ray;

/**
 * {@link LeafFilter} on the Vector API: a leaf's triangles in the four lanes of a 256-bit vector of doubles. Loaded
 * only when the JVM runs with {@code --add-modules jdk.incubator.vector}.
 */
final class VectorLeafFilter extends LeafFilter {
    private static final VectorSpecies<Double> DOUBLES = DoubleVector.SPECIES_256;
    private static final VectorSpecies<Long> LONGS = LongVector.SPECIES_256;
    /** Bit i in lane i: blended by the mask and OR-ed together, it gives the mask as an int. */
    private static final LongVector LANE_BITS = LongVector.broadcast(LONGS, 1)
            .lanewise(VectorOperators.LSHL, LongVector.zero(LONGS).addIndex(1));

    private static final LongVector NO_BITS = LongVector.zero(LONGS);

    /** Refuses where the CPU has no 256-bit vectors; the traversals then test leaves one primitive at a time. */
    VectorLeafFilter() {
        if (DoubleVector.SPECIES_PREFERRED.vectorBitSize() < 256) {
            throw new UnsupportedOperationException("no 256-bit vectors on this CPU");
        }
    }

    /**
     * Written out in one method with no call but the Vector API's, on purpose. JDK 17's optimizing compiler stops
     * inlining ordinary methods once a compilation's graph passes a node count, and the Vector API's operations are
     * many nodes before they fold: a helper for the difference of products, or {@link VectorMask#toLong} (not an
     * intrinsic there), was left a call, and the vectors around it were boxed, 360 bytes per leaf. The mask is read
     * by a blend and an OR across the lanes for the same reason.
     */
    @Override
    int candidates(double[] lanes, int o, int count, Ray ray) {
        // Lane i of coordinate j of vertex v is at o + count (3 v + j) + i: loads of four lanes read past a leaf of
        // fewer than four into its neighbour's (or the array's padding), lanes whose bits the caller ignores.
        int ax = ray.kx(), ay = ray.ky(), az = ray.kz();
        int kx = count * ax, ky = count * ay, kz = count * az;
        // The origin permuted as the axes are (inline: a helper method past the node count would stay a call).
        double x = ray.ox(), y = ray.oy(), z = ray.oz();
        double ox = ax == 0 ? x : ax == 1 ? y : z,
                oy = ay == 0 ? x : ay == 1 ? y : z,
                oz = az == 0 ? x : az == 1 ? y : z;
        double sx = ray.shearX(), sy = ray.shearY();
        int v1 = o + 3 * count, v2 = o + 6 * count;
        // WatertightTriangle.intersect's arithmetic, lane by lane: translate, permute, shear.
        DoubleVector p0z = DoubleVector.fromArray(DOUBLES, lanes, o + kz).sub(oz);
        DoubleVector p1z = DoubleVector.fromArray(DOUBLES, lanes, v1 + kz).sub(oz);
        DoubleVector p2z = DoubleVector.fromArray(DOUBLES, lanes, v2 + kz).sub(oz);
        DoubleVector p0x =
                DoubleVector.fromArray(DOUBLES, lanes, o + kx).sub(ox).add(p0z.mul(sx));
        DoubleVector p0y =
                DoubleVector.fromArray(DOUBLES, lanes, o + ky).sub(oy).add(p0z.mul(sy));
        DoubleVector p1x =
                DoubleVector.fromArray(DOUBLES, lanes, v1 + kx).sub(ox).add(p1z.mul(sx));
        DoubleVector p1y =
                DoubleVector.fromArray(DOUBLES, lanes, v1 + ky).sub(oy).add(p1z.mul(sy));
        DoubleVector p2x =
                DoubleVector.fromArray(DOUBLES, lanes, v2 + kx).sub(ox).add(p2z.mul(sx));
        DoubleVector p2y =
                DoubleVector.fromArray(DOUBLES, lanes, v2 + ky).sub(oy).add(p2z.mul(sy));
        // Edge functions by Util.differenceOfProducts(a, b, c, d): c d, then fma(a, b, -c d) + fma(-c, d, c d).
        DoubleVector c0 = p1y.mul(p2x);
        DoubleVector e0 = p1x.fma(p2y, c0.neg()).add(p1y.neg().fma(p2x, c0));
        DoubleVector c1 = p2y.mul(p0x);
        DoubleVector e1 = p2x.fma(p0y, c1.neg()).add(p2y.neg().fma(p0x, c1));
        DoubleVector c2 = p0y.mul(p1x);
        DoubleVector e2 = p0x.fma(p1y, c2.neg()).add(p0y.neg().fma(p1x, c2));
        // The scalar test's rejections: edge functions of both signs, or a zero determinant. Lanewise MIN and MAX
        // have Math.min and Math.max semantics, which are associative, so the order of the lanes' minimum and
        // maximum does not matter. A NaN (a lane holding no triangle) rejects nothing.
        DoubleVector lowest = e0.min(e1).min(e2), highest = e0.max(e1).max(e2);
        VectorMask<Double> outside = lowest.compare(VectorOperators.LT, 0)
                .and(highest.compare(VectorOperators.GT, 0))
                .or(e0.add(e1).add(e2).compare(VectorOperators.EQ, 0));
        return (int) LANE_BITS.blend(NO_BITS, outside.cast(LONGS)).reduceLanes(VectorOperators.OR);
    }
}
