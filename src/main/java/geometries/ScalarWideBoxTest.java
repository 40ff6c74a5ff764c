package geometries;

/** {@link WideBoxTest} one child box after the other, for JVMs without the Vector API module. */
final class ScalarWideBoxTest extends WideBoxTest {
    @Override
    int test(float[] nodes, int o, RaySlabs r, float tMin, float tMax, float[] entries) {
        // Kept small on purpose: the JIT inlines it into the traversal loop only below 325 bytes of bytecode.
        if (!r.floatSafe) return testInDouble(nodes, o, r, tMin, tMax, entries);
        int nearX = o + BVH.MIN_X + r.flipX, nearY = o + BVH.MIN_Y + r.flipY, nearZ = o + BVH.MIN_Z + r.flipZ;
        int farX = o + BVH.MAX_X - r.flipX, farY = o + BVH.MAX_Y - r.flipY, farZ = o + BVH.MAX_Z - r.flipZ;
        int mask = 0;
        for (int c = 0; c < BVH.WIDTH; c++) {
            // The same operations in the same order as the vector kernel, so both give the same bits.
            float near = max(
                    max(Math.fma(nodes[nearX + c], r.invX, -r.nearX), Math.fma(nodes[nearY + c], r.invY, -r.nearY)),
                    Math.fma(nodes[nearZ + c], r.invZ, -r.nearZ));
            float far = min(
                    min(Math.fma(nodes[farX + c], r.invX, -r.farX), Math.fma(nodes[farY + c], r.invY, -r.farY)),
                    Math.fma(nodes[farZ + c], r.invZ, -r.farZ));
            near = Math.fma(Math.abs(near), -RaySlabs.SLACK, near);
            far = Math.fma(Math.abs(far), RaySlabs.SLACK, far);
            boolean hit = (near <= far) & (near <= tMax) & (far >= tMin);
            entries[c] = hit ? near : MISS;
            mask |= (hit ? 1 : 0) << c;
        }
        return mask;
    }

    /** The vector kernel's max: no operand is NaN, see {@code VectorWideBoxTest}. */
    private static float max(float a, float b) {
        return a < b ? b : a;
    }

    private static float min(float a, float b) {
        return b < a ? b : a;
    }

    @Override
    String name() {
        return "scalar";
    }
}
