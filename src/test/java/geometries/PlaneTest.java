package geometries;

import static geometries.Hits.assertHits;
import static geometries.Hits.assertMiss;
import static geometries.Hits.assertRejected;
import static geometries.Hits.assertVector;
import static geometries.Hits.ray;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Unit tests for {@link Plane}: the course partitions, parallel rays with negative zeros, bad input. */
class PlaneTest {
    private static final double S = 1 / Math.sqrt(3);
    /** The course plane x + y + z = 1 through three points. */
    private final Plane plane = new Plane(new Point(1, 0, 0), new Point(0, 1, 0), new Point(0, 0, 1));

    @Test
    void threePointConstructorGivesTheUnitNormalByVertexOrder() {
        // (p2 - p1) x (p3 - p1) = (-1,1,0) x (-1,0,1) = (1,1,1)
        assertVector(new Vector(S, S, S), plane.getNormal(), "normal");
        assertVector(new Vector(S, S, S), plane.getNormal(new Point(0.5, 0.5, 0)), "normal at a point");
        assertEquals(1, plane.getNormal().length(), 1e-15);
        // the normal is orthogonal to the plane's edges
        assertEquals(0, plane.getNormal().dotProduct(new Vector(-1, 1, 0)), 1e-15);
        assertEquals(0, plane.getNormal().dotProduct(new Vector(-1, 0, 1)), 1e-15);
        // reversed order, reversed normal
        Plane reversed = new Plane(new Point(1, 0, 0), new Point(0, 0, 1), new Point(0, 1, 0));
        assertVector(new Vector(-S, -S, -S), reversed.getNormal(), "reversed");
        assertEquals(new Point(1, 0, 0), plane.getPoint());
    }

    @Test
    void pointNormalConstructorNormalizes() {
        Plane p = new Plane(new Point(0, 0, 5), new Vector(0, 0, 7));
        assertEquals(Vector.AXIS_Z, p.getNormal());
        assertNull(p.getBoundingBox(), "planes are unbounded");
    }

    @Test
    void badInputIsRejected() {
        // BVA: coincident points
        assertRejected(() -> new Plane(new Point(1, 0, 0), new Point(1, 0, 0), new Point(0, 0, 1)), "distinct");
        assertRejected(() -> new Plane(new Point(1, 0, 0), new Point(0, 0, 1), new Point(0, 0, 1)), "distinct");
        assertRejected(() -> new Plane(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 0, 1)), "distinct");
        // BVA: collinear points: the message names them
        assertRejected(
                () -> new Plane(new Point(1, 0, 0), new Point(2, 0, 0), new Point(3, 0, 0)),
                "collinear",
                "(3.0, 0.0, 0.0)");
        assertRejected(() -> new Plane(new Point(1, 1, 1), new Point(2, 2, 2), new Point(-4, -4, -4)), "collinear");
        assertRejected(() -> new Plane(null, Vector.AXIS_Z), "point");
        assertRejected(() -> new Plane(Point.ZERO, null), "normal");
        assertRejected(() -> new Plane(null, Point.ZERO, new Point(1, 0, 0)), "p1");
    }

    // ============ Equivalence Partitions Tests ==============

    @Test
    void tc01RayCrossesThePlane() {
        // (-1,0,0) + s(1,1,1)/sqrt3: x+y+z = -1 + 3s' = 1 at s' = 2/3
        assertHits(plane, ray(-1, 0, 0, 1, 1, 1), "TC01", new Point(-1.0 / 3, 2.0 / 3, 2.0 / 3));
        // from the other side (no back-face culling)
        assertHits(plane, ray(1, 1, 1, -1, -1, 0), "TC01 back", new Point(0, 0, 1));
    }

    @Test
    void tc02RayPointsAwayFromThePlane() {
        assertMiss(plane, ray(2, 0, 0, 1, 1, 1), "TC02");
    }

    // =============== Boundary Values Tests ==================

    @Test
    void rayParallelToThePlane() {
        // TC11: in the plane
        assertMiss(plane, ray(1, 0, 0, -1, 1, 0), "TC11: parallel, included");
        // TC12: not in the plane
        assertMiss(plane, ray(2, 0, 0, -1, 1, 0), "TC12: parallel, outside");
    }

    @Test
    void rayOrthogonalToThePlane() {
        // TC13: before the plane
        assertHits(plane, ray(0, 0, 0, 1, 1, 1), "TC13: before", new Point(1.0 / 3, 1.0 / 3, 1.0 / 3));
        // TC14: in the plane
        assertMiss(plane, ray(0.5, 0.5, 0, 1, 1, 1), "TC14: starts in the plane");
        assertMiss(plane, ray(0.5, 0.5, 0, -1, -1, -1), "TC14: starts in the plane, other way");
        // TC15: after the plane
        assertMiss(plane, ray(1, 1, 1, 1, 1, 1), "TC15: after");
    }

    @Test
    void rayStartingOnThePlane() {
        // TC16: neither orthogonal nor parallel, starting on the plane
        assertMiss(plane, ray(0, 0.5, 0.5, 1, 0, 0), "TC16");
        // TC17: starting at the plane's reference point
        assertMiss(plane, ray(1, 0, 0, 1, 2, 0), "TC17");
    }

    @Test
    void parallelRaysWithNegativeZeroComponents() {
        Plane floor = new Plane(Point.ZERO, Vector.AXIS_Z);
        // dz = -0.0: the denominator is -0.0 which must count as parallel, not as -infinity distances
        assertMiss(floor, ray(0, 0, 1, 1, 1, -0.0), "above, -0.0");
        assertMiss(floor, ray(0, 0, -1, -1, 0, -0.0), "below, -0.0");
        assertMiss(floor, ray(3, 4, 0, 1, -0.0, -0.0), "in the plane, -0.0");
        assertMiss(floor, ray(3, 4, 0, -0.0, 1, 0.0), "in the plane, +0.0");
        Plane negative = new Plane(Point.ZERO, new Vector(-0.0, -0.0, -1));
        assertMiss(negative, ray(0, 0, 1, 1, 0, 0), "negative-zero normal");
        assertHits(negative, ray(0, 0, 1, -0.0, -0.0, -1), "through", new Point(0, 0, 0));
    }

    @Test
    void openIntervalAndCompleteHit() {
        Plane floor = new Plane(new Point(0, 0, -2), Vector.AXIS_Z);
        Ray down = ray(1, 1, 3, 0, 0, -1); // hits at t = 5 exactly
        HitRecord hit = new HitRecord();
        assertTrue(floor.intersect(down, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(5, hit.t);
        assertTrue(!floor.intersect(down, 0, 5, hit.reset()));
        assertTrue(!floor.intersect(down, 5, 10, hit.reset()));
        assertTrue(floor.intersect(down, 4.999, 5.001, hit.reset()));
        floor.completeHit(down, hit);
        assertEquals(new Point(1, 1, -2), hit.point());
        assertEquals(Vector.AXIS_Z, hit.normal());
    }

    @Test
    void farPlaneIsHitAtTheRightDistance() {
        Plane far = new Plane(new Point(0, 0, 1e9), new Vector(0.3, -0.2, 1));
        Vector d = new Vector(0.01, 0.02, 1).normalize();
        HitRecord hit = new HitRecord();
        assertTrue(far.intersect(new Ray(Point.ZERO, d), 0, Double.POSITIVE_INFINITY, hit));
        // n.(o + t d - p) = 0  =>  t = n.p / n.d
        Vector n = new Vector(0.3, -0.2, 1).normalize();
        double expected = (n.z * 1e9) / n.dotProduct(d);
        assertEquals(expected, hit.t, expected * 1e-15);
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 10).mapToObj(i -> Arguments.of(0x91A4EL + 31L * i));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysStartingOnThePlaneFindNothingBeyondRounding(long seed) {
        Plane tilted = new Plane(new Point(1, 2, 3), new Vector(1, -2, 0.5));
        assertTrue(SurfaceStartProperty.check(tilted, new Point(1, 2, 3), 5, false, seed, 300) > 100);
        Plane far = new Plane(new Point(-4e4, 2e4, 1e4), new Vector(0.2, 0.7, -0.1));
        assertTrue(SurfaceStartProperty.check(far, new Point(-4e4, 2e4, 1e4), 100, false, seed, 300) > 100);
    }
}
