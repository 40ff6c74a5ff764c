package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static primitives.Util.differenceOfProducts;

import java.util.SplittableRandom;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * {@link LeafFilter}: a leaf's candidates are exactly the triangles that pass the first checks of
 * {@link WatertightTriangle#intersect} (edge functions of one sign, determinant not zero), computed here the scalar
 * way, lane by lane; so every triangle the scalar test hits is a candidate. On random leaves of one to four
 * primitives, with rays through shared vertices and edges (edge functions exactly zero), along the axes, at
 * coordinates whose edge functions overflow, with shapes other than triangles (always candidates), and with the leaf
 * at the end of its array (its four-lane loads read the padding).
 */
class LeafFilterTest {
    @Test
    void theFilterRunsExactlyWhereTheVectorKernelsDo() throws ReflectiveOperationException {
        if (VectorSupport.available()) {
            assertNotNull(LeafFilter.SELECTED);
        } else {
            assertNull(LeafFilter.SELECTED);
        }
    }

    /**
     * Leaves are filled and filtered for the triangles of meshes of at least {@link LeafFilter#MIN_MESH} triangles
     * only: an icosphere of 1,280, alone or among spheres, but not one of 320, nor a scene of spheres.
     */
    @Test
    void onlyLargeMeshesAreFiltered() throws ReflectiveOperationException {
        boolean available = VectorSupport.available();
        assertTrue(Meshes.icosphere(3).triangleCount() >= LeafFilter.MIN_MESH);
        assertEquals(available, Accelerator.build(Meshes.icosphere(3), true).filtersLeaves());
        Geometries mixed = new Geometries(Meshes.icosphere(3), new Sphere(new Point(3, 0, 0), 1));
        assertEquals(available, Accelerator.build(mixed, true).filtersLeaves());
        assertTrue(Meshes.icosphere(2).triangleCount() < LeafFilter.MIN_MESH);
        assertFalse(Accelerator.build(Meshes.icosphere(2), true).filtersLeaves());
        Geometries spheres = new Geometries(new Sphere(new Point(0, 0, 0), 1), new Sphere(new Point(3, 0, 0), 1));
        assertFalse(Accelerator.build(spheres, true).filtersLeaves());
        assertFalse(Accelerator.build(Meshes.icosphere(3), false).filtersLeaves(), "no tree, no filter");
    }

    static LongStream seeds() {
        return LongStream.range(0, 6).map(i -> 0x1EAFL + 7919L * i);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void candidatesAreTheTrianglesThatPassTheEdgeTest(long seed) throws ReflectiveOperationException {
        assumeTrue(VectorSupport.available(), "needs --add-modules jdk.incubator.vector and 256-bit vectors");
        SplittableRandom random = new SplittableRandom(seed);
        int scalarHits = 0, candidates = 0, boundary = 0;
        for (int c = 0; c < 20_000; c++) {
            int count = 1 + random.nextInt(LeafFilter.LANES);
            // The leaf last in its arrays, after a few others, so that its loads run into the padding.
            int link = random.nextInt(4);
            int n = link + count;
            double[] triangles = new double[9 * n];
            Intersectable[] objects = new Intersectable[n];
            Ray ray = randomRay(random);
            for (int k = 0; k < n; k++) {
                if (random.nextInt(12) == 0) {
                    // Another shape: NaN coordinates, which the filter must pass on.
                    objects[k] = new Sphere(new Point(0, 0, 0), 1);
                    java.util.Arrays.fill(triangles, 9 * k, 9 * k + 9, Double.NaN);
                } else {
                    randomTriangle(triangles, 9 * k, ray, random);
                }
            }
            double[] lanes = new double[triangles.length + LeafFilter.LANES];
            CompiledPrimitives.toLanes(triangles, 9 * link, lanes, 9 * link, count);
            int mask = LeafFilter.SELECTED.candidates(lanes, 9 * link, count, ray);
            for (int i = 0; i < count; i++) {
                int k = link + i;
                boolean expected = objects[k] != null || passesEdgeTest(triangles, 9 * k, ray);
                String where = "case " + c + ", primitive " + i + " of " + count + ", " + ray;
                assertEquals(expected, (mask >> i & 1) == 1, where);
                if (objects[k] != null) continue;
                if (expected) candidates++;
                if (edgeFunctionIsZero(triangles, 9 * k, ray)) boundary++;
                HitRecord hit = new HitRecord();
                boolean hits = WatertightTriangle.intersect(
                        triangles, 9 * k, 9 * k + 3, 9 * k + 6, 7, ray, 0, Double.POSITIVE_INFINITY, hit);
                // Read from the lanes, the scalar test gives the same answer bit for bit.
                HitRecord fromLanes = new HitRecord();
                int a = 9 * link + i;
                boolean hitsInLanes = WatertightTriangle.intersect(
                        lanes, a, a + 3 * count, a + 6 * count, count, 7, ray, 0, Double.POSITIVE_INFINITY, fromLanes);
                assertEquals(hits, hitsInLanes, where);
                if (hits) {
                    scalarHits++;
                    assertTrue(expected, "a hit the filter dropped: " + where);
                    assertEquals(Double.doubleToRawLongBits(hit.t), Double.doubleToRawLongBits(fromLanes.t), where);
                    assertEquals(Double.doubleToRawLongBits(hit.u), Double.doubleToRawLongBits(fromLanes.u), where);
                    assertEquals(Double.doubleToRawLongBits(hit.v), Double.doubleToRawLongBits(fromLanes.v), where);
                }
            }
        }
        // The cases reach what they are meant to: hits, candidates, and points on edges.
        assertTrue(scalarHits > 1000, "hits " + scalarHits);
        assertTrue(candidates > scalarHits, "candidates " + candidates);
        assertTrue(boundary > 100, "rays through edges or vertices " + boundary);
    }

    /** The first checks of the watertight test, written the scalar way: what a lane must compute. */
    private static boolean passesEdgeTest(double[] v, int o, Ray ray) {
        double[] e = edgeFunctions(v, o, ray);
        double lowest = Math.min(e[0], Math.min(e[1], e[2])), highest = Math.max(e[0], Math.max(e[1], e[2]));
        return !(lowest < 0 && highest > 0) && e[0] + e[1] + e[2] != 0;
    }

    private static boolean edgeFunctionIsZero(double[] v, int o, Ray ray) {
        double[] e = edgeFunctions(v, o, ray);
        return e[0] == 0 || e[1] == 0 || e[2] == 0;
    }

    private static double[] edgeFunctions(double[] v, int o, Ray ray) {
        int kx = ray.kx(), ky = ray.ky(), kz = ray.kz();
        double[] origin = {ray.ox(), ray.oy(), ray.oz()};
        double[] px = new double[3], py = new double[3];
        for (int i = 0; i < 3; i++) {
            double z = v[o + 3 * i + kz] - origin[kz];
            px[i] = v[o + 3 * i + kx] - origin[kx] + ray.shearX() * z;
            py[i] = v[o + 3 * i + ky] - origin[ky] + ray.shearY() * z;
        }
        return new double[] {
            differenceOfProducts(px[1], py[2], py[1], px[2]),
            differenceOfProducts(px[2], py[0], py[2], px[0]),
            differenceOfProducts(px[0], py[1], py[0], px[1])
        };
    }

    private static Ray randomRay(SplittableRandom random) {
        Point origin = new Point(grid(random), grid(random), grid(random) + 3);
        double[] d = new double[3];
        do {
            for (int a = 0; a < 3; a++) d[a] = random.nextInt(4) == 0 ? 0 : random.nextDouble(-1, 1);
        } while (d[0] == 0 && d[1] == 0 && d[2] == 0);
        return new Ray(origin, new Vector(d[0], d[1], d[2]));
    }

    /** A coordinate on a coarse grid half the time, so that rays and vertices line up exactly. */
    private static double grid(SplittableRandom random) {
        return random.nextBoolean() ? random.nextInt(-2, 3) * 0.5 : random.nextDouble(-1, 1);
    }

    /**
     * A triangle near the ray: through a point on it, a vertex on it, or off it; now and then of huge coordinates
     * (edge functions that overflow) or of no area.
     */
    private static void randomTriangle(double[] v, int o, Ray ray, SplittableRandom random) {
        double t = random.nextDouble(0.5, 6);
        double[] center = {ray.ox() + t * ray.dx(), ray.oy() + t * ray.dy(), ray.oz() + t * ray.dz()};
        int kind = random.nextInt(10);
        double scale = kind == 0 ? 1e200 : random.nextDouble(0.01, 2);
        for (int i = 0; i < 3; i++) {
            for (int a = 0; a < 3; a++) {
                double offset = kind == 1 && i == 0 ? 0 : random.nextDouble(-1, 1) * scale;
                v[o + 3 * i + a] = kind == 2 && i == 2 ? v[o + 3 + a] : center[a] + offset;
            }
        }
        if (kind == 3) {
            // Vertices on the grid: rays from grid points meet them and their edges exactly.
            for (int j = 0; j < 9; j++) v[o + j] = random.nextInt(-2, 3) * 0.5;
        }
    }
}
