package geometries;

import static geometries.Hits.assertHits;
import static geometries.Hits.assertMiss;
import static geometries.Hits.assertRejected;
import static geometries.Hits.assertVector;
import static geometries.Hits.ray;
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

/** Unit tests for {@link Cylinder}: radius 1 around the z axis from z = 0 to z = 2 unless said otherwise. */
class CylinderTest {
    private final Cylinder cylinder = new Cylinder(1, new Ray(Point.ZERO, Vector.AXIS_Z), 2);

    @Test
    void badInput() {
        Ray axis = new Ray(Point.ZERO, Vector.AXIS_Z);
        assertRejected(() -> new Cylinder(1, axis, 0), "height", "0.0");
        assertRejected(() -> new Cylinder(1, axis, -3), "height", "-3.0");
        assertRejected(() -> new Cylinder(1, axis, Double.NaN), "height", "NaN");
        assertRejected(() -> new Cylinder(0, axis, 1), "radius", "0.0");
        assertRejected(() -> new Cylinder(-1, axis, 1), "radius", "-1.0");
        assertEquals(2, cylinder.getHeight());
    }

    @Test
    void getNormal() {
        // EP: side, bottom cap, top cap
        assertVector(new Vector(1, 0, 0), cylinder.getNormal(new Point(1, 0, 1)), "side");
        assertVector(new Vector(0, 0, -1), cylinder.getNormal(new Point(0.5, 0, 0)), "bottom");
        assertVector(new Vector(0, 0, 1), cylinder.getNormal(new Point(0, 0.5, 2)), "top");
        // BVA: the centres of the caps
        assertVector(new Vector(0, 0, -1), cylinder.getNormal(new Point(0, 0, 0)), "bottom centre");
        assertVector(new Vector(0, 0, 1), cylinder.getNormal(new Point(0, 0, 2)), "top centre");
    }

    // ============ Equivalence Partitions Tests ==============

    @Test
    void rayCrossesTheSideTwice() {
        assertHits(cylinder, ray(-2, 0, 1, 1, 0, 0), "TC01", new Point(-1, 0, 1), new Point(1, 0, 1));
    }

    @Test
    void rayCrossesSideAndCap() {
        // (-2,0,0.5) + s(1,0,1): side x = -1 at s = 1, top z = 2 at s = 1.5
        assertHits(cylinder, ray(-2, 0, 0.5, 1, 0, 1), "TC02", new Point(-1, 0, 1.5), new Point(-0.5, 0, 2));
        // and the reverse way
        assertHits(cylinder, ray(-0.5, 0, 2, -1, 0, -1), "TC03 from the top cap", new Point(-1, 0, 1.5));
        assertHits(cylinder, ray(0.5, 0, 3, -1, 0, -1), "TC04", new Point(-0.5, 0, 2), new Point(-1, 0, 1.5));
    }

    @Test
    void rayCrossesBothCaps() {
        assertHits(cylinder, ray(0.2, 0.3, -1, 0.1, 0, 1), "TC05", new Point(0.3, 0.3, 0), new Point(0.5, 0.3, 2));
    }

    @Test
    void rayStartsInside() {
        assertHits(cylinder, ray(0, 0, 1, 1, 0, 0), "TC06: to the side", new Point(1, 0, 1));
        assertHits(cylinder, ray(0, 0, 1, 0, 0, 1), "TC07: to the top", new Point(0, 0, 2));
        assertHits(cylinder, ray(0, 0, 1, 0, 0, -1), "TC08: to the bottom", new Point(0, 0, 0));
    }

    @Test
    void rayMisses() {
        assertMiss(cylinder, ray(-2, 0, 3, 1, 0, 0), "TC09: above");
        assertMiss(cylinder, ray(-2, 0, -1, 1, 0, 0), "TC10: below");
        assertMiss(cylinder, ray(-2, 2, 1, 1, 0, 0), "TC11: beside");
        assertMiss(cylinder, ray(2, 0, 1, 1, 0, 0), "TC12: going away");
        // the infinite tube would be hit here, the finite cylinder is not
        assertMiss(cylinder, ray(-2, 0, 5, 1, 0, 0.1), "TC13: above, oblique");
    }

    // =============== Boundary Values Tests ==================

    @Test
    void rayParallelToTheAxis() {
        // TC14: inside: both caps
        assertHits(cylinder, ray(0.5, 0, -1, 0, 0, 1), "TC14", new Point(0.5, 0, 0), new Point(0.5, 0, 2));
        // TC15: with negative zeros
        assertHits(cylinder, ray(0.5, 0, -1, -0.0, -0.0, 1), "TC15", new Point(0.5, 0, 0), new Point(0.5, 0, 2));
        assertHits(cylinder, ray(0.5, 0, 3, 0.0, -0.0, -1), "TC16", new Point(0.5, 0, 2), new Point(0.5, 0, 0));
        // TC17: on the axis
        assertHits(cylinder, ray(0, 0, -1, 0, 0, 1), "TC17", new Point(0, 0, 0), new Point(0, 0, 2));
        // TC18: on the surface: the rim belongs to the caps, so it is hit at both rims
        assertHits(cylinder, ray(1, 0, -1, 0, 0, 1), "TC18", new Point(1, 0, 0), new Point(1, 0, 2));
        // TC19: outside
        assertMiss(cylinder, ray(1.5, 0, -1, 0, 0, 1), "TC19");
        assertMiss(cylinder, ray(1.5, 0, -1, -0.0, 0, 1), "TC20");
    }

    @Test
    void rayThroughTheRim() {
        // (-2,0,-1) + s(1,0,1): the bottom rim at (-1,0,0), then the top rim at (1,0,2): once each
        List<Point> points = cylinder.findIntersections(ray(-2, 0, -1, 1, 0, 1));
        Hits.assertPoints(points, 1e-12, "TC21: rim to rim", new Point(-1, 0, 0), new Point(1, 0, 2));
        // from inside through the top rim
        Hits.assertPoints(
                cylinder.findIntersections(ray(0, 0, 1, 1, 0, 1)),
                1e-12,
                "TC22: out through the rim",
                new Point(1, 0, 2));
    }

    @Test
    void rayStartsOnTheSurface() {
        assertMiss(cylinder, ray(1, 0, 1, 1, 0, 0), "TC23: side, outward");
        assertHits(cylinder, ray(1, 0, 1, -1, 0, 0), "TC24: side, inward", new Point(-1, 0, 1));
        assertMiss(cylinder, ray(0.5, 0, 2, 0, 0, 1), "TC25: top, outward");
        assertHits(cylinder, ray(0.5, 0, 2, 0, 0, -1), "TC26: top, inward", new Point(0.5, 0, 0));
        assertMiss(cylinder, ray(0, 0, 0, 1, 0, -1), "TC27: bottom centre, outward");
    }

    @Test
    void rayInACapPlane() {
        // lies in the plane of the bottom cap: grazing, no crossing
        assertMiss(cylinder, ray(-2, 0, 0, 1, 0, 0), "TC28: in the bottom plane");
        assertMiss(cylinder, ray(-2, 0.5, 2, 1, 0, -0.0), "TC29: in the top plane, -0.0");
    }

    @Test
    void boundingBoxOfATiltedCylinder() {
        // axis from (0,0,0) along (1,1,0), height sqrt 2: the caps are discs tilted 45 degrees
        Cylinder tilted = new Cylinder(1, new Ray(Point.ZERO, new Vector(1, 1, 0)), Math.sqrt(2));
        BoundingBox box = tilted.getBoundingBox();
        double e = Math.sqrt(0.5); // half-extent of a cap disc along x and y
        assertEquals(-e, box.minX, 1e-9);
        assertEquals(-e, box.minY, 1e-9);
        assertEquals(-1, box.minZ, 1e-9);
        assertEquals(1 + e, box.maxX, 1e-9);
        assertEquals(1 + e, box.maxY, 1e-9);
        assertEquals(1, box.maxZ, 1e-9);
        // conservative: random surface points of the rims are inside
        Random random = new Random(7);
        Vector u = new Vector(1, -1, 0).normalize(), w = Vector.AXIS_Z;
        for (int i = 0; i < 1000; i++) {
            double a = random.nextDouble() * 2 * Math.PI;
            Point rim = Point.ZERO.add(u.scale(Math.cos(a)).add(w.scale(Math.sin(a) + 1e-300)));
            assertTrue(box.contains(rim), "bottom rim " + rim);
            assertTrue(box.contains(rim.add(new Vector(1, 1, 0))), "top rim");
        }
    }

    @Test
    void boundingBoxOfAnAxisAlignedCylinder() {
        BoundingBox box = cylinder.getBoundingBox();
        assertEquals(-1, box.minX, 1e-9);
        assertEquals(1, box.maxY, 1e-9);
        assertEquals(0, box.minZ, 1e-9);
        assertEquals(2, box.maxZ, 1e-9);
        assertTrue(box.contains(new Point(1, 0, 2)));
        assertTrue(box.contains(new Point(0, -1, 0)));
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 10).mapToObj(i -> Arguments.of(0xC71DL + 17L * i));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysStartingOnTheSurfaceFindOnlyTheFarSide(long seed) {
        Cylinder tilted = new Cylinder(1.5, new Ray(new Point(1, 2, 3), new Vector(1, 1, -2)), 4);
        assertTrue(SurfaceStartProperty.check(tilted, new Point(1.8, 2.8, 1.4), 2, true, seed, 400) > 100);
    }

    /**
     * Rays entering just inside the rim (on the cap 1e-12 from the rim, or on the side 1e-12 from the cap) cross
     * the closed surface exactly twice: no slipping between cap and side, no double count.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysNearTheRimCrossTheSurfaceTwice(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 300; i++) {
            double a = random.nextDouble() * 2 * Math.PI;
            boolean top = random.nextBoolean();
            boolean onCap = random.nextBoolean();
            double radial = onCap ? 1 - 1e-12 : 1;
            double z = onCap ? (top ? 2 : 0) : (top ? 2 - 1e-12 : 1e-12);
            Point entry = new Point(radial * Math.cos(a), radial * Math.sin(a), z);
            Point inside = new Point(
                    0.8 * (random.nextDouble() - 0.5),
                    0.8 * (random.nextDouble() - 0.5),
                    0.2 + 1.6 * random.nextDouble());
            Vector d = inside.subtract(entry).normalize();
            Ray ray = new Ray(entry.add(d.scale(-3)), d);
            List<Point> points = cylinder.findIntersections(ray);
            String where = "seed " + seed + " case " + i + " entering at " + entry + ": " + points;
            assertEquals(2, points.size(), where);
            assertEquals(0, points.get(0).distance(entry), 1e-11, where);
        }
    }
}
