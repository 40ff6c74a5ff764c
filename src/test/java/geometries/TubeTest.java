package geometries;

import static geometries.Hits.assertHits;
import static geometries.Hits.assertMiss;
import static geometries.Hits.assertRejected;
import static geometries.Hits.assertVector;
import static geometries.Hits.ray;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Unit tests for {@link Tube}: an infinite tube, radius 1 around the z axis unless said otherwise. */
class TubeTest {
    private final Tube tube = new Tube(1, new Ray(Point.ZERO, Vector.AXIS_Z));

    @Test
    void accessorsAndBadInput() {
        assertEquals(1, tube.getRadius());
        assertEquals(Vector.AXIS_Z, tube.getAxis().getDirection());
        assertNull(tube.getBoundingBox(), "an infinite tube is unbounded");
        assertRejected(() -> new Tube(0, new Ray(Point.ZERO, Vector.AXIS_Z)), "radius", "0.0");
        assertRejected(() -> new Tube(-2, new Ray(Point.ZERO, Vector.AXIS_Z)), "radius", "-2.0");
        assertRejected(() -> new Tube(Double.NaN, new Ray(Point.ZERO, Vector.AXIS_Z)), "radius", "NaN");
        assertRejected(() -> new Tube(1, null), "axis");
    }

    @Test
    void getNormal() {
        // EP: a point on the side
        assertVector(new Vector(1, 0, 0), tube.getNormal(new Point(1, 0, 5)), "above the head");
        assertVector(new Vector(0, -1, 0), tube.getNormal(new Point(0, -1, -3)), "below the head");
        double s = Math.sqrt(0.5);
        assertVector(new Vector(s, s, 0), tube.getNormal(new Point(s, s, 2)), "diagonal");
        // BVA: the point is level with the axis head (the projection on the axis is the head itself)
        assertVector(new Vector(0, 1, 0), tube.getNormal(new Point(0, 1, 0)), "level with the head");
        // a tilted axis: normal is orthogonal to the axis and points away from it
        Tube tilted = new Tube(2, new Ray(new Point(1, 1, 1), new Vector(1, 1, 0)));
        Vector n = tilted.getNormal(new Point(3, 3, 3)); // 2 above the axis point (3,3,1)
        assertVector(Vector.AXIS_Z, n, "tilted");
    }

    // ============ Equivalence Partitions Tests ==============

    @Test
    void rayCrossesTheTube() {
        // TC01: orthogonal to the axis, crossing it
        assertHits(tube, ray(-2, 0, 0.5, 1, 0, 0), "TC01", new Point(-1, 0, 0.5), new Point(1, 0, 0.5));
        // TC02: oblique: (-2,0,0) + s(1,0,1) meets |x| = 1 at s = 1 and s = 3
        assertHits(tube, ray(-2, 0, 0, 1, 0, 1), "TC02", new Point(-1, 0, 1), new Point(1, 0, 3));
        // TC03: oblique, not through the axis: y = 0.6 => x = -+0.8
        assertHits(tube, ray(-2, 0.6, 4, 1, 0, 0), "TC03", new Point(-0.8, 0.6, 4), new Point(0.8, 0.6, 4));
    }

    @Test
    void rayStartsInside() {
        assertHits(tube, ray(0.5, 0, 0, 1, 0, 0), "TC04", new Point(1, 0, 0));
        assertHits(tube, ray(0, 0, 5, 0, 1, 0), "TC05: on the axis", new Point(0, 1, 5));
        assertHits(tube, ray(0, 0, 0, 0, 3, 4), "TC06: from the head, oblique", new Point(0, 1, 4.0 / 3));
    }

    @Test
    void rayMissesTheTube() {
        assertMiss(tube, ray(2, 0, 0, 1, 0, 0), "TC07: outside, going away");
        assertMiss(tube, ray(-2, 2, 0, 1, 0, 0), "TC08: line outside");
        assertMiss(tube, ray(-2, 1, 0, 1, 0, 0), "TC09: tangent");
        assertMiss(tube, ray(-2, 1, 0, 1, 0, 1), "TC10: tangent, oblique");
    }

    // =============== Boundary Values Tests ==================

    @Test
    void rayStartsOnTheSurface() {
        assertMiss(tube, ray(1, 0, 0, 1, 0, 0), "TC11: outward");
        assertHits(tube, ray(1, 0, 0, -1, 0, 0), "TC12: inward, through the axis", new Point(-1, 0, 0));
        assertHits(tube, ray(0, -1, 3, 0, 1, 1), "TC13: inward, oblique", new Point(0, 1, 5));
    }

    @Test
    void rayParallelToTheAxis() {
        assertMiss(tube, ray(0.5, 0, 0, 0, 0, 1), "TC14: inside");
        assertMiss(tube, ray(0, 0, -1, 0, 0, 1), "TC15: on the axis");
        assertMiss(tube, ray(1, 0, 0, 0, 0, 1), "TC16: on the surface");
        assertMiss(tube, ray(3, 0, 0, 0, 0, -1), "TC17: outside");
        // negative zero components
        assertMiss(tube, ray(0.5, 0, 0, -0.0, 0.0, -1), "TC18: inside, -0.0");
        assertMiss(tube, ray(0.5, 0.2, 0, -0.0, -0.0, 1), "TC19: inside, -0.0 both");
        assertMiss(tube, ray(1, 0, 0, -0.0, 0.0, 1), "TC20: on the surface, -0.0");
        // the axis given with negative zeros
        Tube negative = new Tube(1, new Ray(Point.ZERO, new Vector(-0.0, -0.0, -1)));
        assertMiss(negative, ray(0.5, 0, 0, 0, 0, 1), "TC21: axis with -0.0");
        assertHits(negative, ray(0, 0, 0, -0.0, 1, 0), "TC22: across, -0.0", new Point(0, 1, 0));
    }

    @Test
    void tiltedTube() {
        // axis through (1,1,1) along (1,1,1); a ray through the axis point (2,2,2) perpendicular to it
        Vector axis = new Vector(1, 1, 1).normalize();
        Tube tilted = new Tube(2, new Ray(new Point(1, 1, 1), new Vector(1, 1, 1)));
        Vector across = new Vector(1, -1, 0).normalize();
        Point c = new Point(2, 2, 2);
        List<Point> points = tilted.findIntersections(new Ray(c.add(across.scale(-5)), across));
        Hits.assertPoints(points, 1e-12, "tilted", c.add(across.scale(-2)), c.add(across.scale(2)));
        // the normals there are +- across
        assertVector(across.scale(-1), tilted.getNormal(points.get(0)), "normal 0");
        assertVector(across, tilted.getNormal(points.get(1)), "normal 1");
        assertEquals(0, tilted.getNormal(points.get(1)).dotProduct(axis), 1e-12);
    }

    @Test
    void nearlyParallelRayStillHitsAtTheRightDistance() {
        // direction (1e-8, 0, 1): from (0,0,0) it leaves the unit tube at z = 1e8
        HitRecord hit = new HitRecord();
        assertTrue(tube.intersect(ray(0, 0, 0, 1e-8, 0, 1), 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Math.sqrt(1 + 1e16), hit.t, 1e-6);
    }

    @Test
    void nearTangentRaysAreClassifiedByTheirExactDistanceFromTheAxis() {
        // rays along x at height y, in planes across the axis: they cross the unit tube iff |y| < 1
        for (int k = -4; k <= 4; k++) {
            double y = 1;
            for (int i = 0; i < Math.abs(k); i++) y = k < 0 ? Math.nextDown(y) : Math.nextUp(y);
            for (double start : new double[] {-5, -1e6}) {
                int count = tube.findIntersections(ray(start, y, 3, 1, 0, 0)).size();
                assertEquals(y < 1 ? 2 : 0, count, "y = 1 " + (k < 0 ? "- " : "+ ") + Math.abs(k) + " ulp");
            }
        }
    }

    @Test
    void completeHit() {
        Ray r = ray(-2, 0.6, 4, 1, 0, 0);
        HitRecord hit = new HitRecord();
        assertTrue(tube.intersect(r, 0, Double.POSITIVE_INFINITY, hit));
        tube.completeHit(r, hit);
        assertEquals(0, hit.point().distance(new Point(-0.8, 0.6, 4)), 1e-15);
        assertVector(new Vector(-0.8, 0.6, 0), hit.normal(), "outward normal");
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 10).mapToObj(i -> Arguments.of(0x70BEL + 131L * i));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysStartingOnTheSurfaceFindOnlyTheFarSide(long seed) {
        Tube tilted = new Tube(1.5, new Ray(new Point(1, 2, 3), new Vector(1, 1, -2)));
        assertTrue(SurfaceStartProperty.check(tilted, new Point(1, 2, 3), 3, true, seed, 400) > 100);
    }
}
