package geometries;

import static geometries.Hits.assertHits;
import static geometries.Hits.assertMiss;
import static geometries.Hits.assertRejected;
import static geometries.Hits.assertVector;
import static geometries.Hits.ray;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
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

/** Unit tests for {@link Sphere}: the course partitions plus the numerically hard cases. */
class SphereTest {
    /** The course sphere: centre (1,0,0), radius 1. */
    private final Sphere sphere = new Sphere(new Point(1, 0, 0), 1);

    @Test
    void constructorsAndAccessors() {
        assertEquals(new Point(1, 0, 0), sphere.getCenter());
        assertEquals(1, sphere.getRadius());
        Sphere courseOrder = new Sphere(2, new Point(1, 2, 3));
        assertEquals(2, courseOrder.getRadius());
        assertEquals(new Point(1, 2, 3), courseOrder.getCenter());
    }

    @Test
    void badInputNamesTheParameterAndValue() {
        assertRejected(() -> new Sphere(Point.ZERO, 0), "radius", "0.0");
        assertRejected(() -> new Sphere(Point.ZERO, -1), "radius", "-1.0");
        assertRejected(() -> new Sphere(Point.ZERO, Double.NaN), "radius", "NaN");
        assertRejected(() -> new Sphere(Point.ZERO, Double.POSITIVE_INFINITY), "radius", "Infinity");
        assertRejected(() -> new Sphere(null, 1), "center");
        // radii whose square is not a usable positive double
        assertRejected(() -> new Sphere(Point.ZERO, 1e-200), "radius", "1.0E-200");
        assertRejected(() -> new Sphere(Point.ZERO, 1e200), "radius", "1.0E200");
    }

    @Test
    void getNormal() {
        // EP: a point on the sphere: the unit outward normal
        assertVector(new Vector(1, 0, 0), sphere.getNormal(new Point(2, 0, 0)), "at (2,0,0)");
        assertVector(new Vector(0, 0, -1), sphere.getNormal(new Point(1, 0, -1)), "at (1,0,-1)");
        double s = Math.sqrt(0.5);
        assertVector(new Vector(s, s, 0), sphere.getNormal(new Point(1 + s, s, 0)), "at 45 degrees");
        assertEquals(1, sphere.getNormal(new Point(1 + s, s, 0)).length(), 1e-15);
    }

    // ============ Equivalence Partitions Tests ==============

    @Test
    void tc01LineOutsideTheSphere() {
        assertMiss(sphere, ray(-1, 0, 0, 1, 1, 0), "TC01: line outside");
    }

    @Test
    void tc02RayStartsBeforeAndCrossesTheSphere() {
        // The course values: (0.0651530771650466, 0.355051025721682, 0) and (1.53484692283495, 0.844948974278318, 0)
        Ray ray = ray(-1, 0, 0, 3, 1, 0);
        List<Point> points = sphere.findIntersections(ray);
        Hits.assertPoints(
                points,
                1e-4,
                "TC02: starts before, crosses",
                new Point(0.0652, 0.3551, 0),
                new Point(1.5348, 0.8449, 0));
        // and exactly, by hand: y = (x + 1) / 3 and (x-1)^2 + y^2 = 1  =>  10x^2 - 16x + 1 = 0
        double x0 = (16 - Math.sqrt(216)) / 20, x1 = (16 + Math.sqrt(216)) / 20;
        assertHits(sphere, ray, "TC02 exact", new Point(x0, (x0 + 1) / 3, 0), new Point(x1, (x1 + 1) / 3, 0));
    }

    @Test
    void tc03RayStartsInside() {
        // on the same line as TC02, from (0.5, 0.5, 0): only the far point
        double x1 = (16 + Math.sqrt(216)) / 20;
        assertHits(sphere, ray(0.5, 0.5, 0, 3, 1, 0), "TC03: starts inside", new Point(x1, (x1 + 1) / 3, 0));
    }

    @Test
    void tc04RayStartsAfterTheSphere() {
        assertMiss(sphere, ray(2, 1, 0, 3, 1, 0), "TC04: starts after");
    }

    // =============== Boundary Values Tests ==================

    @Test
    void rayLineCrossesTheSphereButNotTheCentre() {
        // TC11: starts at the sphere and goes inside: the start point itself is not an intersection
        assertHits(sphere, ray(1, -1, 0, 1, 1, 0), "TC11: starts on sphere, inward", new Point(2, 0, 0));
        // TC12: starts at the sphere and goes outside
        assertMiss(sphere, ray(2, 0, 0, 1, 1, 0), "TC12: starts on sphere, outward");
    }

    @Test
    void rayLineGoesThroughTheCentre() {
        // TC13: starts before the sphere
        assertHits(sphere, ray(-1, 0, 0, 1, 0, 0), "TC13: before", new Point(0, 0, 0), new Point(2, 0, 0));
        // TC14: starts at the sphere and goes inside
        assertHits(sphere, ray(0, 0, 0, 1, 0, 0), "TC14: on sphere, inward", new Point(2, 0, 0));
        // TC15: starts inside
        assertHits(sphere, ray(0.5, 0, 0, 1, 0, 0), "TC15: inside", new Point(2, 0, 0));
        // TC16: starts at the centre
        assertHits(sphere, ray(1, 0, 0, 0, 1, 0), "TC16: at centre", new Point(1, 1, 0));
        // TC17: starts at the sphere and goes outside
        assertMiss(sphere, ray(2, 0, 0, 1, 0, 0), "TC17: on sphere, outward");
        // TC18: starts after the sphere
        assertMiss(sphere, ray(3, 0, 0, 1, 0, 0), "TC18: after");
    }

    @Test
    void rayLineIsTangent() {
        // tangent point (1, 1, 0): touching is not crossing
        assertMiss(sphere, ray(0, 1, 0, 1, 0, 0), "TC19: before the tangent point");
        assertMiss(sphere, ray(1, 1, 0, 1, 0, 0), "TC20: at the tangent point");
        assertMiss(sphere, ray(2, 1, 0, 1, 0, 0), "TC21: after the tangent point");
    }

    @Test
    void rayOrthogonalToTheLineFromItsHeadToTheCentre() {
        // TC22: head outside the sphere
        assertMiss(sphere, ray(-1, 0, 0, 0, 1, 0), "TC22: orthogonal, outside");
        // TC23: head inside the sphere
        assertHits(sphere, ray(1.5, 0, 0, 0, 0, 1), "TC23: orthogonal, inside", new Point(1.5, 0, Math.sqrt(0.75)));
    }

    @Test
    void openIntervalOfTheClosestHitQuery() {
        // From (-1,0,0) along x: t = 1 and t = 3 exactly
        Ray ray = ray(-1, 0, 0, 1, 0, 0);
        HitRecord hit = new HitRecord();
        assertTrue(sphere.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(1, hit.t);
        assertSame(sphere, hit.geometry);
        // tMin is excluded: starting at t = 1 the closest hit is the far one
        assertTrue(sphere.intersect(ray, 1, Double.POSITIVE_INFINITY, hit.reset()));
        assertEquals(3, hit.t);
        // tMax is excluded
        assertFalse(sphere.intersect(ray, 0, 1, hit.reset()));
        assertTrue(sphere.intersect(ray, 0, Math.nextUp(1.0), hit.reset()));
        assertFalse(sphere.intersect(ray, 1, 3, hit.reset()));
        // a miss leaves the record untouched
        hit.reset();
        hit.t = 42;
        assertFalse(sphere.intersect(ray, 5, 10, hit));
        assertEquals(42, hit.t);
        assertEquals(null, hit.geometry);
    }

    @Test
    void completeHitGivesSurfacePointNormalAndErrorBound() {
        Ray ray = ray(-1, 0.5, 0, 1, 0, 0);
        HitRecord hit = new HitRecord();
        assertTrue(sphere.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        sphere.completeHit(ray, hit);
        // entry point: x = 1 - sqrt(0.75)
        Point expected = new Point(1 - Math.sqrt(0.75), 0.5, 0);
        assertEquals(0, hit.point().distance(expected), 1e-15);
        assertVector(new Vector(-Math.sqrt(0.75), 0.5, 0), hit.normal(), "outward normal");
        assertEquals(hit.normal(), hit.shadingNormal());
        // the error bound is positive but tiny at unit scale
        assertTrue(hit.errorX > 0 && hit.errorX < 1e-14, "errorX " + hit.errorX);
        assertEquals(1, hit.point().distance(sphere.getCenter()), 1e-15);
    }

    @Test
    void boundingBoxContainsTheSphereTightly() {
        BoundingBox box = new Sphere(new Point(1, 2, 3), 2).getBoundingBox();
        assertEquals(-1, box.minX, 1e-12);
        assertEquals(0, box.minY, 1e-12);
        assertEquals(1, box.minZ, 1e-12);
        assertEquals(3, box.maxX, 1e-12);
        assertEquals(4, box.maxY, 1e-12);
        assertEquals(5, box.maxZ, 1e-12);
        // conservative: the extreme points are inside
        assertTrue(box.contains(new Point(-1, 2, 3)));
        assertTrue(box.contains(new Point(1, 2, 5)));
    }

    // =============== Hard cases ==================

    @Test
    void unitSphereFarAwayIsHitAtTheExactDistance() {
        // A unit sphere 1e8 away: the textbook discriminant b^2 - c cancels completely here
        Sphere far = new Sphere(new Point(1e8, 0, 0), 1);
        HitRecord hit = new HitRecord();
        assertTrue(far.intersect(ray(0, 0, 0, 1, 0, 0), 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(1e8 - 1, hit.t, 1e-7);
        // passing at 0.5 from the centre: t = 1e8 -+ sqrt(0.75)
        Sphere offset = new Sphere(new Point(1e8, 0.5, 0), 1);
        List<Point> points = offset.findIntersections(ray(0, 0, 0, 1, 0, 0));
        assertEquals(2, points.size(), "both crossings of a far sphere: " + points);
        assertEquals(1e8 - Math.sqrt(0.75), points.get(0).x, 1e-7);
        assertEquals(1e8 + Math.sqrt(0.75), points.get(1).x, 1e-7);
        // an oblique direction: centre exactly 1e8 along (1,2,3)/sqrt(14) (to rounding)
        Vector d = new Vector(1, 2, 3).normalize();
        Sphere oblique = new Sphere(new Point(1e8 * d.x, 1e8 * d.y, 1e8 * d.z), 1);
        assertTrue(oblique.intersect(new Ray(Point.ZERO, d), 0, Double.POSITIVE_INFINITY, hit.reset()));
        assertEquals(1e8 - 1, hit.t, 1e-6);
    }

    @Test
    void tinySphereIsHit() {
        Sphere tiny = new Sphere(new Point(0, 0, 10), 1e-9);
        List<Point> points = tiny.findIntersections(ray(0, 0, 0, 0, 0, 1));
        assertEquals(2, points.size(), points.toString());
        assertEquals(10 - 1e-9, points.get(0).z, 1e-15);
        assertEquals(10 + 1e-9, points.get(1).z, 1e-15);
    }

    @Test
    void nearTangentRaysAreClassifiedByTheirExactDistanceFromTheCentre() {
        // Rays along x at height y: they cross the unit sphere at the origin iff |y| < 1.
        // The set-up makes the offset from the centre exact, so the decision is exact too.
        Sphere unit = new Sphere(Point.ZERO, 1);
        for (int k = -4; k <= 4; k++) {
            double y = k < 0 ? below(1.0, -k) : above(1.0, k);
            for (double start : new double[] {-5, -1e6}) {
                int count = unit.findIntersections(ray(start, y, 0, 1, 0, 0)).size();
                assertEquals(y < 1 ? 2 : 0, count, "y = 1 " + (k < 0 ? "- " : "+ ") + Math.abs(k) + " ulp");
            }
        }
    }

    private static double below(double x, int ulps) {
        for (int i = 0; i < ulps; i++) x = Math.nextDown(x);
        return x;
    }

    private static double above(double x, int ulps) {
        for (int i = 0; i < ulps; i++) x = Math.nextUp(x);
        return x;
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 20).mapToObj(i -> Arguments.of(0x5FE7E5L + 104729L * i));
    }

    /**
     * Random rays passing at a chosen distance s from the centre of random spheres: s clearly below r crosses
     * twice, clearly above misses; within a relative 1e-9 of r either is fine but never one hit from outside.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void nearTangentRandomRaysAreConsistent(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 300; i++) {
            double r = Math.pow(10, random.nextInt(9) - 4);
            Point c = new Point(
                    (random.nextDouble() - 0.5) * 1e3,
                    (random.nextDouble() - 0.5) * 1e3,
                    (random.nextDouble() - 0.5) * 1e3);
            Sphere s = new Sphere(c, r);
            Vector d = new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
            Vector perp = d.perpendicular();
            double ratio = 1 + (random.nextDouble() - 0.5) * (random.nextBoolean() ? 1e-6 : 1e-2);
            double back = r * (2 + 100 * random.nextDouble());
            Point head = c.add(perp.scale(ratio * r)).add(d.scale(-back));
            Ray ray = new Ray(head, d);
            int count = s.findIntersections(ray).size();
            String where = "seed " + seed + " case " + i + ": r=" + r + " ratio=" + ratio + " " + ray;
            if (ratio < 1 - 1e-9) assertEquals(2, count, where);
            else if (ratio > 1 + 1e-9) assertEquals(0, count, where);
            else assertTrue(count == 0 || count == 2, where + " count " + count);
        }
    }

    /**
     * Random rays starting on the sphere (a refined hit point): inward ones find the far side at distance
     * {@code -2 r cos}, outward ones nothing beyond rounding distance.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysStartingOnTheSurface(long seed) {
        Random random = new Random(seed);
        Sphere s = new Sphere(new Point(3, -2, 7), 2.5);
        for (int i = 0; i < 300; i++) {
            Vector n = SurfaceStartProperty.randomUnit(random);
            HitRecord hit = new HitRecord();
            Ray probe = new Ray(s.getCenter().add(n.scale(10)), n.scale(-1));
            assertTrue(s.intersect(probe, 0, Double.POSITIVE_INFINITY, hit));
            s.completeHit(probe, hit);
            Point p = hit.point();
            Vector d = SurfaceStartProperty.randomUnit(random);
            double cos = d.dotProduct(hit.normal());
            if (Math.abs(cos) < 1e-3) continue; // grazing directions are not part of this property
            List<Point> points = s.findIntersections(new Ray(p, d)).stream()
                    .filter(q -> q.distance(p) > 1e-9)
                    .toList();
            String where = "seed " + seed + " case " + i + " from " + p + " along " + d + " -> " + points;
            if (cos < 0) {
                assertEquals(1, points.size(), where);
                assertEquals(-2 * s.getRadius() * cos, points.get(0).distance(p), 1e-9, where);
            } else {
                assertEquals(0, points.size(), where);
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysStartingOnTheSurfaceOfFarSpheres(long seed) {
        Point c = new Point(1e5, -3e5, 2e5);
        assertTrue(SurfaceStartProperty.check(new Sphere(c, 40), c, 30, true, seed, 200) > 50);
    }
}
