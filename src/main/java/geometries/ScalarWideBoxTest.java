package geometries;

import primitives.Ray;

/** {@link WideBoxTest} one child box after the other, for JVMs without the Vector API module. */
final class ScalarWideBoxTest extends WideBoxTest {
    @Override
    int test(float[] nodes, int o, Ray ray, int signs, double tMin, double tMax, double[] entries) {
        // Kept small on purpose: the JIT inlines it into the traversal loop only below 325 bytes of bytecode.
        if ((signs & BoundingBox.FINITE_RECIPROCALS) == 0) {
            return testWithInfiniteReciprocals(nodes, o, ray, signs, tMin, tMax, entries);
        }
        // The near plane of each slab is the minimum for a positive direction and the maximum for a negative one.
        int flipX = (signs & 1) * BVH.MAX_X, flipY = (signs >> 1 & 1) * BVH.MAX_X, flipZ = (signs >> 2 & 1) * BVH.MAX_X;
        int nearX = o + BVH.MIN_X + flipX, nearY = o + BVH.MIN_Y + flipY, nearZ = o + BVH.MIN_Z + flipZ;
        int farX = o + BVH.MAX_X - flipX, farY = o + BVH.MAX_Y - flipY, farZ = o + BVH.MAX_Z - flipZ;
        double ox = ray.ox(), oy = ray.oy(), oz = ray.oz(), ix = ray.invDx(), iy = ray.invDy(), iz = ray.invDz();
        int mask = 0;
        for (int c = 0; c < BVH.WIDTH; c++) {
            double near = Math.max(
                    Math.max((nodes[nearX + c] - ox) * ix, (nodes[nearY + c] - oy) * iy), (nodes[nearZ + c] - oz) * iz);
            double far = Math.min(
                    Math.min((nodes[farX + c] - ox) * ix, (nodes[farY + c] - oy) * iy), (nodes[farZ + c] - oz) * iz);
            near -= Math.abs(near) * BoundingBox.SLAB_SLACK;
            far += Math.abs(far) * BoundingBox.SLAB_SLACK;
            boolean hit = (near <= far) & (near <= tMax) & (far >= tMin);
            entries[c] = hit ? near : BoundingBox.MISS;
            mask |= (hit ? 1 : 0) << c;
        }
        return mask;
    }

    @Override
    String name() {
        return "scalar";
    }
}
