package geometries;

import benchmark.RaySets;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * JMH micro-benchmarks of the BVH kernels, each reported as nanoseconds per operation: the ray-box slab test the
 * traversal runs on float child boxes, the watertight ray-triangle test, a leaf of four triangles tested one by one
 * and through the leaf filter, and full closest-hit traversals of the
 * 100k-triangle heightfield with coherent and incoherent rays. It lives in package {@code geometries} to reach the
 * package-private kernels. Run with {@code mvn -q -Pjmh clean compile exec:exec}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class KernelBenchmark {
    /** Rays per invocation: enough to average over hits and misses, few enough to stay in cache. */
    static final int RAYS = 4096;

    Accelerator heightfield;
    Ray[] coherent;
    Ray[] incoherent;
    /** The root node with its child boxes, as the traversal sees them. */
    float[] boxes;

    float[] entries = new float[BVH.WIDTH];
    RaySlabs slabs = new RaySlabs();
    /** One triangle (9 doubles) that about half of the incoherent rays from above hit. */
    double[] triangle = {-1, -1, 0, 1, -1, 0.1, 0, 1, -0.1};

    HitRecord hit = new HitRecord();

    /** Four triangles, the one above and three moved copies, as nine doubles each and as a leaf's lanes. */
    double[] fourTriangles = new double[4 * 9];

    double[] fourLanes = new double[4 * 9 + LeafFilter.LANES];

    @Setup
    public void setUp() {
        heightfield = Accelerator.build(Meshes.heightfield(224), true);
        Ray[] image =
                RaySets.pinhole(new Point(0, -0.5, 1.8), new Point(0, 0.05, 0), new Vector(0, 0, 1), 45, 1024, 1024);
        // A 64 x 64 tile from the middle of the image: neighbouring rays, as a renderer's tile would trace them.
        coherent = new Ray[RAYS];
        for (int j = 0; j < 64; j++) {
            for (int i = 0; i < 64; i++) coherent[64 * j + i] = image[(480 + j) * 1024 + 480 + i];
        }
        incoherent = RaySets.incoherent(heightfield.getBoundingBox(), RAYS, 20240613L);
        boxes = java.util.Arrays.copyOf(heightfield.getBvh().nodes, BVH.NODE_STRIDE);
        for (int t = 0; t < 4; t++) {
            for (int j = 0; j < 9; j++) fourTriangles[9 * t + j] = triangle[j] + (j % 3 == t % 3 ? 0.5 * t : 0);
        }
        CompiledPrimitives.toLanes(fourTriangles, 0, fourLanes, 0, 4);
    }

    /** The child boxes of the root node, with the kernel this JVM selected (per box tested). */
    @Benchmark
    @OperationsPerInvocation(BVH.WIDTH * RAYS)
    public int slabTest() {
        int hits = 0;
        for (Ray ray : incoherent) {
            slabs.set(ray);
            hits += Integer.bitCount(WideBoxTest.SELECTED.test(boxes, 0, slabs, 0, WideBoxTest.MISS, entries));
        }
        return hits;
    }

    /** The same boxes through the double path that rays with a zero direction component take. */
    @Benchmark
    @OperationsPerInvocation(BVH.WIDTH * RAYS)
    public int slabTestComparisons() {
        int hits = 0;
        for (Ray ray : incoherent) {
            slabs.set(ray);
            slabs.floatSafe = false;
            hits += Integer.bitCount(WideBoxTest.SELECTED.test(boxes, 0, slabs, 0, WideBoxTest.MISS, entries));
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int triangleTest() {
        int hits = 0;
        for (Ray ray : incoherent) {
            if (WatertightTriangle.intersect(
                    triangle, 0, 3, 6, WatertightTriangle.ALL_EDGES_SHARED, ray, 0, Double.POSITIVE_INFINITY, hit)) {
                hits++;
            }
        }
        return hits;
    }

    /** Four triangles one after the other, as a leaf is tested without the filter (per leaf). */
    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int fourTriangleTests() {
        int hits = 0;
        for (Ray ray : incoherent) {
            for (int o = 0; o < 36; o += 9) {
                if (hits(fourTriangles, o, 1, ray)) hits++;
            }
        }
        return hits;
    }

    /**
     * The same four triangles through the leaf filter, then the watertight test of its candidates in the lanes, as a
     * filled leaf is tested (per leaf; the scalar test's figure where the JVM has no filter).
     */
    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int fourTrianglesFiltered() {
        if (LeafFilter.SELECTED == null) return fourTriangleTests();
        int hits = 0;
        for (Ray ray : incoherent) {
            for (int c = LeafFilter.SELECTED.candidates(fourLanes, 0, 4, ray) & 15; c != 0; c &= c - 1) {
                if (hits(fourLanes, Integer.numberOfTrailingZeros(c), 4, ray)) hits++;
            }
        }
        return hits;
    }

    /** The watertight test of the triangle at {@code v[a]}, its coordinates {@code stride} apart. */
    private boolean hits(double[] v, int a, int stride, Ray ray) {
        return WatertightTriangle.intersect(
                v,
                a,
                a + 3 * stride,
                a + 6 * stride,
                stride,
                WatertightTriangle.ALL_EDGES_SHARED,
                ray,
                0,
                Double.POSITIVE_INFINITY,
                hit);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int traversalCoherent() {
        return traverse(coherent);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int traversalIncoherent() {
        return traverse(incoherent);
    }

    private int traverse(Ray[] rays) {
        int hits = 0;
        for (Ray ray : rays) {
            if (heightfield.intersect(ray, 0, Double.POSITIVE_INFINITY, hit)) hits++;
        }
        return hits;
    }
}
