package geometries;

import static geometries.Hits.assertHits;
import static geometries.Hits.assertMiss;
import static geometries.Hits.assertRejected;
import static geometries.Hits.assertVector;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link Triangle}: the course triangle (0,0,1), (1,0,0), (0,1,0) in the plane x + y + z = 1. A
 * lone triangle excludes its boundary: rays through an edge, a vertex or an edge's continuation miss it.
 */
class TriangleTest {
    private static final double S = 1 / Math.sqrt(3);
    private final Triangle triangle = new Triangle(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0));

    /**
     * Directions in which rays are fired at target points of the plane (both sides, oblique and axis). Their
     * normalized components have exact ratios, so the watertight test's shear is exact and a ray aimed at an edge
     * really passes through it; for other directions rounding decides on which side of the edge the ray passes.
     */
    private static final Vector[] EXACT_DIRECTIONS = {
        new Vector(-1, -1, -1),
        new Vector(1, 1, 1),
        new Vector(0, 0, 1),
        new Vector(0, 0, -1),
        new Vector(-1, -2, -2),
        new Vector(2, 1, 2),
        new Vector(1, 0, 0)
    };

    /** Exact directions plus one whose rounding is arbitrary (for targets clearly inside or outside). */
    private static final Vector[] DIRECTIONS = {
        new Vector(-1, -1, -1),
        new Vector(1, 1, 1),
        new Vector(0, 0, 1),
        new Vector(0, 0, -1),
        new Vector(-1, -2, -2),
        new Vector(2, 1, 2),
        new Vector(1, 0, 0),
        new Vector(-0.3, -0.7, -1.1)
    };

    /** A ray through {@code target} along {@code d}, starting at {@code target - d} (exact for dyadic values). */
    static Ray through(Point target, Vector d) {
        return new Ray(new Point(target.x - d.x, target.y - d.y, target.z - d.z), d);
    }

    @Test
    void normalFollowsTheVertexOrder() {
        assertVector(new Vector(S, S, S), triangle.getNormal(new Point(0.2, 0.3, 0.5)), "normal");
        Triangle reversed = new Triangle(new Point(0, 0, 1), new Point(0, 1, 0), new Point(1, 0, 0));
        assertVector(new Vector(-S, -S, -S), reversed.getNormal(new Point(0.2, 0.3, 0.5)), "reversed");
        assertEquals(List.of(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0)), triangle.getVertices());
    }

    @Test
    void degenerateTrianglesAreRejected() {
        // collinear
        assertRejected(
                () -> new Triangle(new Point(0, 0, 0), new Point(1, 1, 1), new Point(2, 2, 2)),
                "degenerate triangle",
                "collinear");
        // coincident vertices
        assertRejected(
                () -> new Triangle(new Point(1, 2, 3), new Point(1, 2, 3), new Point(0, 0, 1)), "degenerate triangle");
        assertRejected(
                () -> new Triangle(new Point(1, 2, 3), new Point(1, 2, 3), new Point(1, 2, 3)), "degenerate triangle");
        // null vertices name which one
        assertRejected(() -> new Triangle(null, new Point(1, 0, 0), new Point(0, 1, 0)), "p0");
        assertRejected(() -> new Triangle(new Point(1, 0, 0), null, new Point(0, 1, 0)), "p1");
        assertRejected(() -> new Triangle(new Point(1, 0, 0), new Point(0, 1, 0), null), "p2");
        // but a thin, valid sliver is fine
        new Triangle(new Point(0, 0, 0), new Point(1, 0, 0), new Point(0.5, 1e-9, 0));
    }

    // ============ Equivalence Partitions Tests ==============

    @Test
    void tc01InsideTheTriangle() {
        Point inside = new Point(0.2, 0.3, 0.5);
        for (Vector d : DIRECTIONS) {
            List<Point> points = triangle.findIntersections(through(inside, d));
            Hits.assertPoints(points, 1e-14, "TC01 along " + d, inside);
        }
    }

    @Test
    void tc02OutsideAgainstAnEdge() {
        for (Point outside :
                new Point[] {new Point(1, 1, -1), new Point(-0.5, 0.75, 0.75), new Point(0.75, -0.5, 0.75)}) {
            for (Vector d : DIRECTIONS) assertMiss(triangle, through(outside, d), "TC02 " + outside + " along " + d);
        }
    }

    @Test
    void tc03OutsideAgainstAVertex() {
        for (Point outside :
                new Point[] {new Point(-0.5, -0.5, 2), new Point(2, -0.5, -0.5), new Point(-0.5, 2, -0.5)}) {
            for (Vector d : DIRECTIONS) assertMiss(triangle, through(outside, d), "TC03 " + outside + " along " + d);
        }
    }

    // =============== Boundary Values Tests ==================

    @Test
    void tc11OnAnEdgeIsNotAHit() {
        for (Point onEdge : new Point[] {
            new Point(0.5, 0.5, 0), new Point(0, 0.25, 0.75), new Point(0.75, 0, 0.25), new Point(0.5, 0, 0.5)
        }) {
            for (Vector d : EXACT_DIRECTIONS)
                assertMiss(triangle, through(onEdge, d), "TC11 " + onEdge + " along " + d);
        }
    }

    @Test
    void tc12OnAVertexIsNotAHit() {
        for (Point vertex : triangle.getVertices()) {
            for (Vector d : EXACT_DIRECTIONS)
                assertMiss(triangle, through(vertex, d), "TC12 " + vertex + " along " + d);
        }
    }

    @Test
    void tc13OnAnEdgesContinuationIsNotAHit() {
        for (Point continuation : new Point[] {
            new Point(2, -1, 0), new Point(-1, 2, 0), new Point(0, -1, 2), new Point(0, 2, -1), new Point(1.5, 0, -0.5)
        }) {
            for (Vector d : EXACT_DIRECTIONS) {
                assertMiss(triangle, through(continuation, d), "TC13 " + continuation + " along " + d);
            }
        }
    }

    @Test
    void raysInOrParallelToThePlane() {
        // parallel, outside the plane
        assertMiss(triangle, Hits.ray(0, 0, 0, 1, -1, 0), "parallel");
        assertMiss(triangle, Hits.ray(0, 0, 0, 1, -1, -0.0), "parallel, -0.0");
        // in the plane, crossing the triangle: seen edge-on, no hit
        assertMiss(triangle, Hits.ray(-1, 0.5, 1.5, 1, 0, -1), "in the plane");
    }

    @Test
    void raysStartingOnTheTriangle() {
        Point inside = new Point(0.2, 0.3, 0.5);
        for (Vector d : DIRECTIONS) assertMiss(triangle, new Ray(inside, d), "starting inside, along " + d);
        // starting behind and pointing away
        assertMiss(triangle, Hits.ray(0, 0, 0, -1, -1, -1), "behind, away");
        // from the back side: no culling
        assertHits(triangle, Hits.ray(0, 0, 0, 1, 1, 1), "back side", new Point(S * S, S * S, S * S));
    }

    @Test
    void openIntervalAndCompleteHit() {
        // from (0.2, 0.3, -1) straight up: z = 0.5 at t = 1.5
        Ray up = Hits.ray(0.2, 0.3, -1, 0, 0, 1);
        HitRecord hit = new HitRecord();
        assertTrue(triangle.intersect(up, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(1.5, hit.t, 1e-15);
        assertTrue(!triangle.intersect(up, 0, 1.4, new HitRecord()));
        assertTrue(!triangle.intersect(up, 1.6, 10, new HitRecord()));
        triangle.completeHit(up, hit);
        assertEquals(0, hit.point().distance(new Point(0.2, 0.3, 0.5)), 1e-15);
        assertVector(new Vector(S, S, S), hit.normal(), "hit normal");
        assertTrue(hit.errorX >= 0 && hit.errorX < 1e-14);
    }

    @Test
    void boundingBox() {
        BoundingBox box = triangle.getBoundingBox();
        assertEquals(new BoundingBox(0, 0, 0, 1, 1, 1), box);
    }

    @Test
    void farTriangleIsHit() {
        // a unit triangle 1e7 away
        Triangle far = new Triangle(new Point(1e7, 0, 0), new Point(1e7, 1, 0), new Point(1e7, 0, 1));
        List<Point> points = far.findIntersections(Hits.ray(0, 0.25, 0.25, 1, 0, 0));
        Hits.assertPoints(points, 1e-8, "far", new Point(1e7, 0.25, 0.25));
    }

    /**
     * Vertices near 1e200 around a ray along +z: the edge functions' products overflow, and Kahan's correction
     * subtracts infinities, so some edge functions are NaN (the rejection by their minimum and maximum lets those
     * through). The test must still answer a miss, not a hit at a NaN distance, and leave the record as it was,
     * wherever the triangle lies: around the ray, beside it, behind it.
     */
    @ParameterizedTest(name = "triangle shifted by ({0}, {1}), at z = {2}")
    @MethodSource("overflowingTriangles")
    void edgeFunctionsThatOverflowGiveAMissAndLeaveTheRecord(double dx, double dy, double z) {
        double big = 1e200;
        double[] v = {big + dx, big + dy, z, -big + dx, big + dy, z, dx, -big + dy, z};
        HitRecord hit = new HitRecord();
        hit.t = 42;
        Ray ray = new Ray(Point.ZERO, new Vector(0, 0, 1));
        boolean hits = WatertightTriangle.intersect(
                v, 0, 3, 6, WatertightTriangle.ALL_EDGES_SHARED, ray, 0, Double.POSITIVE_INFINITY, hit);
        assertTrue(!hits && hit.t == 42, "a triangle with overflowing edge functions must be missed, record untouched");
    }

    static Stream<Arguments> overflowingTriangles() {
        return Stream.of(
                Arguments.of(0, 0, 5),
                Arguments.of(0, 0, -5),
                Arguments.of(3e200, 0, 5),
                Arguments.of(0, -3e200, 5),
                Arguments.of(1e199, 1e199, 1e200));
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 20).mapToObj(i -> Arguments.of(0x7A1L + 7L * i));
    }

    /**
     * Random triangles and rays aimed at points given by barycentric coordinates: clearly inside (all > 1e-6)
     * hits at that point, at the distance from the ray head; clearly outside (one < -1e-6) misses.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void randomTrianglesAgreeWithBarycentricCoordinates(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 200; i++) {
            Point a = randomPoint(random), b = randomPoint(random), c = randomPoint(random);
            Triangle t;
            try {
                t = new Triangle(a, b, c);
            } catch (IllegalArgumentException degenerate) {
                continue;
            }
            double b1 = random.nextDouble() * 1.6 - 0.3, b2 = random.nextDouble() * 1.6 - 0.3;
            double b0 = 1 - b1 - b2;
            double min = Math.min(b0, Math.min(b1, b2));
            if (Math.abs(min) < 1e-6) continue;
            Point target = new Point(
                    b0 * a.x + b1 * b.x + b2 * c.x, b0 * a.y + b1 * b.y + b2 * c.y, b0 * a.z + b1 * b.z + b2 * c.z);
            Vector d = SurfaceStartProperty.randomUnit(random);
            // skip rays nearly in the plane of the triangle, where the barycentrics are ill-conditioned
            if (Math.abs(d.dotProduct(t.getNormal(target))) < 1e-3) continue;
            double back = 1 + 10 * random.nextDouble();
            Ray ray = new Ray(target.add(d.scale(-back)), d); // rounding may move the line by ~1e-15: see margin
            List<Point> points = t.findIntersections(ray);
            String where = "seed " + seed + " case " + i + ": " + t.getVertices() + " b=(" + b0 + "," + b1 + "," + b2
                    + ") " + ray + " -> " + points;
            if (min > 0) {
                assertEquals(1, points.size(), where);
                assertEquals(0, points.get(0).distance(target), 1e-9, where);
                HitRecord hit = new HitRecord();
                assertTrue(t.intersect(ray, 0, Double.POSITIVE_INFINITY, hit), where);
                assertEquals(back, hit.t, 1e-9, where);
            } else {
                assertEquals(0, points.size(), where);
            }
        }
    }

    private static Point randomPoint(Random random) {
        return new Point(random.nextGaussian() * 3, random.nextGaussian() * 3, random.nextGaussian() * 3);
    }
}
