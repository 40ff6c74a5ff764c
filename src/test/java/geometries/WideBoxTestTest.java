package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The two kernels of {@link WideBoxTest}: the JVM picks the vectorized one exactly when the Vector API module is
 * present (surefire runs the BVH tests both with and without it), and both give the same masks and the same
 * entry distances, on random boxes and rays and on the hard cases: rays in a box's face plane, with zero direction
 * components, from inside a box, toward empty slots, through flat boxes.
 */
class WideBoxTestTest {
    @Test
    void theVectorizedKernelRunsExactlyWhenTheModuleIsPresent() throws ReflectiveOperationException {
        assertEquals(VectorSupport.available() ? "vector" : "scalar", WideBoxTest.SELECTED.name());
    }

    @Test
    void scalarAndVectorKernelsAgree() throws ReflectiveOperationException {
        assumeTrue(VectorSupport.available(), "needs --add-modules jdk.incubator.vector and 256-bit vectors");
        WideBoxTest vector = (WideBoxTest) Class.forName("geometries.VectorWideBoxTest")
                .getDeclaredConstructor()
                .newInstance();
        // The mask read the other way than this JDK's default (VectorMask.toLong or an OR across the lanes).
        boolean defaultToLong = Class.forName("geometries.VectorWideBoxTest")
                .getDeclaredField("MASK_TO_LONG")
                .getBoolean(null);
        WideBoxTest other = (WideBoxTest) Class.forName("geometries.VectorWideBoxTest")
                .getDeclaredConstructor(boolean.class)
                .newInstance(!defaultToLong);
        float[] c2 = new float[BVH.WIDTH];
        WideBoxTest scalar = new ScalarWideBoxTest();
        SplittableRandom random = new SplittableRandom(42);
        float[] nodes = new float[BVH.NODE_STRIDE];
        float[] a = new float[BVH.WIDTH], b = new float[BVH.WIDTH];
        RaySlabs slabs = new RaySlabs();
        int hits = 0;
        for (int i = 0; i < 100_000; i++) {
            randomNode(nodes, random);
            Ray ray = randomRay(nodes, random);
            double tMin = random.nextInt(4) == 0 ? random.nextDouble() : 0;
            double tMax = random.nextInt(3) == 0 ? tMin + 5 * random.nextDouble() : Double.POSITIVE_INFINITY;
            slabs.set(ray);
            float lo = RaySlabs.below(tMin), hi = RaySlabs.above(tMax);
            int maskA = scalar.test(nodes, 0, slabs, lo, hi, a);
            int maskB = vector.test(nodes, 0, slabs, lo, hi, b);
            String where = "case " + i + ": " + ray + " in (" + tMin + ", " + tMax + ")";
            assertEquals(maskA, maskB, where);
            assertEquals(maskA, other.test(nodes, 0, slabs, lo, hi, c2), where + " (mask read the other way)");
            for (int c = 0; c < BVH.WIDTH; c++) {
                assertEquals(
                        Float.floatToRawIntBits(a[c]),
                        Float.floatToRawIntBits(b[c]),
                        where + " child " + c + ": " + a[c] + " vs " + b[c]);
            }
            hits += Integer.bitCount(maskA);
        }
        // The cases must exercise both answers.
        assertTrue(hits > 40_000 && hits < 760_000, "hits " + hits);
    }

    @Test
    void emptySlotsAreNeverHit() {
        float[] nodes = new float[BVH.NODE_STRIDE];
        for (int c = 0; c < BVH.WIDTH; c++) {
            for (int a = 0; a < 3; a++) {
                nodes[BVH.MIN_X + BVH.WIDTH * a + c] = Float.POSITIVE_INFINITY;
                nodes[BVH.MAX_X + BVH.WIDTH * a + c] = Float.NEGATIVE_INFINITY;
            }
        }
        float[] entries = new float[BVH.WIDTH];
        float[] misses = new float[BVH.WIDTH];
        java.util.Arrays.fill(misses, WideBoxTest.MISS);
        RaySlabs slabs = new RaySlabs();
        Vector[] directions = {
            new Vector(1, 2, 3), new Vector(-1, 2, -3), new Vector(0, 0, 1), new Vector(0, -1, 0), new Vector(1, 0, 0)
        };
        for (Vector d : directions) {
            Ray ray = new Ray(new Point(0.5, -0.25, 2), d);
            slabs.set(ray);
            assertEquals(0, WideBoxTest.SELECTED.test(nodes, 0, slabs, 0, Float.POSITIVE_INFINITY, entries));
            assertArrayEquals(misses, entries);
        }
    }

    /**
     * The float kernel never misses what exact arithmetic hits: every box that the slab test in double (without
     * margins, so within 2^-52 of exact) finds within the interval is in the mask, entered no later than the double
     * distance, for rays from near and from far (1e6) from the world's origin and aimed at box corners and edges,
     * where a hit is decided by the last bits.
     */
    @Test
    void theFloatTestIsConservative() {
        SplittableRandom random = new SplittableRandom(7);
        float[] nodes = new float[BVH.NODE_STRIDE];
        float[] entries = new float[BVH.WIDTH];
        RaySlabs slabs = new RaySlabs();
        int grazing = 0;
        for (int i = 0; i < 200_000; i++) {
            double shift = random.nextInt(3) == 0 ? 1e6 : random.nextInt(2) == 0 ? 1e3 : 0;
            randomNode(nodes, random);
            for (int k = 0; k < 6 * BVH.WIDTH; k++) nodes[k] += (float) shift;
            int target = random.nextInt(BVH.WIDTH);
            double[] aim = new double[3], o = new double[3];
            for (int a = 0; a < 3; a++) {
                double lo = nodes[BVH.MIN_X + BVH.WIDTH * a + target], hi = nodes[BVH.MAX_X + BVH.WIDTH * a + target];
                if (!(lo <= hi)) lo = hi = shift;
                // A corner or edge coordinate most of the time: the ray grazes the box.
                aim[a] = random.nextInt(3) == 0 ? lo + random.nextDouble() * (hi - lo) : random.nextBoolean() ? lo : hi;
                o[a] = aim[a] + (random.nextDouble() - 0.5) * (random.nextInt(4) == 0 ? 1e4 : 10);
            }
            Vector d = new Vector(aim[0] - o[0], aim[1] - o[1], aim[2] - o[2]);
            Ray ray = new Ray(new Point(o[0], o[1], o[2]), d);
            slabs.set(ray);
            int mask = WideBoxTest.SELECTED.test(nodes, 0, slabs, 0, Float.POSITIVE_INFINITY, entries);
            for (int c = 0; c < BVH.WIDTH; c++) {
                if (!(nodes[BVH.MIN_X + c] <= nodes[BVH.MAX_X + c])) continue; // an empty slot
                double near = 0, far = Double.POSITIVE_INFINITY;
                double[] origin = {ray.ox(), ray.oy(), ray.oz()}, inv = {ray.invDx(), ray.invDy(), ray.invDz()};
                for (int a = 0; a < 3; a++) {
                    double t0 = (nodes[BVH.MIN_X + BVH.WIDTH * a + c] - origin[a]) * inv[a];
                    double t1 = (nodes[BVH.MAX_X + BVH.WIDTH * a + c] - origin[a]) * inv[a];
                    if (!(t0 <= t1)) {
                        double t = t0;
                        t0 = t1;
                        t1 = t;
                    }
                    if (t0 > near) near = t0;
                    if (t1 < far) far = t1;
                }
                if (!(near <= far)) continue;
                if (far - near <= 1e-9 * Math.max(1, far)) grazing++;
                String where = "case " + i + " child " + c + ": " + ray;
                assertTrue((mask >> c & 1) == 1, where + " missed, double enters at " + near);
                assertTrue(entries[c] <= near, where + " entered at " + entries[c] + " after " + near);
            }
        }
        assertTrue(grazing > 1000, "grazing cases " + grazing);
    }

    /** Eight boxes: mostly random, some flat, some sharing face planes, some empty slots. */
    private static void randomNode(float[] nodes, SplittableRandom random) {
        for (int c = 0; c < BVH.WIDTH; c++) {
            boolean empty = random.nextInt(8) == 0;
            for (int a = 0; a < 3; a++) {
                float lo = (float) (random.nextInt(4) == 0 ? random.nextInt(3) - 1 : 4 * random.nextDouble() - 2);
                float hi = random.nextInt(6) == 0 ? lo : lo + (float) (2 * random.nextDouble());
                nodes[BVH.MIN_X + BVH.WIDTH * a + c] = empty ? Float.POSITIVE_INFINITY : lo;
                nodes[BVH.MAX_X + BVH.WIDTH * a + c] = empty ? Float.NEGATIVE_INFINITY : hi;
            }
        }
    }

    /**
     * Rays from random points or box corners toward a random point of a random box (so about half the tests hit),
     * some along the axes or in a coordinate plane.
     */
    private static Ray randomRay(float[] nodes, SplittableRandom random) {
        double[] o = new double[3], d = new double[3];
        int corner = random.nextInt(BVH.WIDTH), target = random.nextInt(BVH.WIDTH);
        for (int a = 0; a < 3; a++) {
            o[a] = random.nextInt(3) == 0
                    ? nodes[(random.nextBoolean() ? BVH.MIN_X : BVH.MAX_X) + BVH.WIDTH * a + corner]
                    : 8 * random.nextDouble() - 4;
            if (!Double.isFinite(o[a])) o[a] = 0.5;
            double lo = nodes[BVH.MIN_X + BVH.WIDTH * a + target], hi = nodes[BVH.MAX_X + BVH.WIDTH * a + target];
            double aim = lo <= hi ? lo + random.nextDouble() * (hi - lo) : random.nextDouble();
            d[a] = random.nextInt(5) == 0 ? 0 : aim - o[a] + 0.2 * (random.nextDouble() - 0.5);
        }
        if (d[0] == 0 && d[1] == 0 && d[2] == 0) d[2] = 1;
        return new Ray(new Point(o[0], o[1], o[2]), new Vector(d[0], d[1], d[2]));
    }
}
