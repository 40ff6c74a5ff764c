package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * Shadow queries within an aimed beam ({@link Accelerator#aimShadowBeam}) give the brute-force scan's answers bit for
 * bit: whether light passes and the transmittance product, for rays inside the beam, on its rim, just outside it
 * (which search the tree), from beams too wide to hold their leaves, and from starts that reuse another start's search.
 */
class ShadowBeamTest {
    static Stream<Arguments> seeds() {
        return LongStream.range(0, 5).mapToObj(i -> Arguments.of(0xBEA3L + 7919L * i));
    }

    /** A point within {@code r} of {@code c} per axis; on a corner of that cube every fourth time. */
    private static Point near(Point c, double r, Random random) {
        if (random.nextInt(4) == 0) {
            return new Point(
                    c.x + (random.nextBoolean() ? r : -r),
                    c.y + (random.nextBoolean() ? r : -r),
                    c.z + (random.nextBoolean() ? r : -r));
        }
        return new Point(
                c.x + r * (2 * random.nextDouble() - 1),
                c.y + r * (2 * random.nextDouble() - 1),
                c.z + r * (2 * random.nextDouble() - 1));
    }

    private static void assertSameAnswer(Accelerator beamed, Accelerator brute, Ray ray, double tMax, HitRecord beam) {
        HitRecord plain = new HitRecord();
        boolean expected = brute.passesLight(ray, 0, tMax, plain);
        String where = ray + " to " + tMax;
        assertEquals(expected, beamed.passesLight(ray, 0, tMax, beam), where);
        assertEquals(plain.transmitR, beam.transmitR, 0, where);
        assertEquals(plain.transmitG, beam.transmitG, 0, where);
        assertEquals(plain.transmitB, beam.transmitB, 0, where);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void raysInAndAroundABeamAnswerAsTheScanDoes(long seed) {
        Random random = new Random(seed);
        Geometries scene = AcceleratorTest.randomScene(random, 200);
        for (int i = 0; i < 30; i++) {
            Sphere clear = new Sphere(new Point(random.nextGaussian() * 8, random.nextGaussian() * 8, 0), 1);
            clear.setMaterial(new Material().setKt(1));
            scene.add(clear);
        }
        Accelerator bvh = Accelerator.build(scene, true), brute = Accelerator.build(scene, false);
        HitRecord beam = new HitRecord();
        int collected = 0, rays = 0, blocked = 0;
        for (int b = 0; b < 300; b++) {
            Point p = new Point(random.nextGaussian() * 12, random.nextGaussian() * 12, random.nextGaussian() * 12);
            Point c = new Point(random.nextGaussian() * 12, random.nextGaussian() * 12, random.nextGaussian() * 12);
            double radius = b % 10 == 0 ? 20 : 0.05 + random.nextDouble() * 2;
            int slot = random.nextInt(3) + (b % 7 == 0 ? HitRecord.BEAM_SLOTS : 0); // some fold onto others
            for (int start = 0; start < 3; start++) {
                // Later starts lie within 0.9 of the radius of the first: they may reuse its search.
                Point from = start == 0 ? p : near(p, 0.9 * radius, random);
                bvh.aimShadowBeam(beam, slot, from.x, from.y, from.z, c.x, c.y, c.z, radius);
                for (int i = 0; i < 6; i++) {
                    // Now and then a ray that leaves the beam a little, which must search the tree.
                    double spread = i == 5 ? 1.5 * radius : radius;
                    Point origin = random.nextBoolean() ? from : near(from, 0.05 * radius, random);
                    Point end = near(c, spread, random);
                    Vector d = end.subtract(origin);
                    double length = d.length();
                    Ray ray = new Ray(origin, d);
                    assertSameAnswer(bvh, brute, ray, length, beam);
                    rays++;
                    if (beam.transmitR == 0) blocked++;
                }
                if (beam.activeBeam.collected()) collected++;
            }
        }
        assertTrue(collected > 300, "most beams hold their leaves: " + collected + " of 900 starts");
        assertTrue(
                blocked > rays / 20 && blocked < rays - rays / 20, "a fair share blocked: " + blocked + " of " + rays);
    }

    /**
     * A small opaque triangle across each ray from a corner of its beam's start to a corner of its end: the ray finds
     * it only if the beam's search kept the leaves at the beam's very rim.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void leavesAtTheRimOfTheBeamAreFound(long seed) {
        Random random = new Random(seed);
        Geometries scene = new Geometries();
        int beams = 200;
        Point[] p = new Point[beams], c = new Point[beams], from = new Point[beams], to = new Point[beams];
        double[] radii = new double[beams];
        for (int b = 0; b < beams; b++) {
            double scale = b % 4 == 0 ? 1e4 : 10; // far from the origin too: the margins are relative
            p[b] = new Point(random.nextGaussian() * scale, random.nextGaussian() * scale, random.nextGaussian());
            // Every fifth beam straight up an axis, which the search tilts.
            double sideways = b % 5 == 1 ? 0 : 20;
            c[b] = p[b].add(new Vector(
                    random.nextGaussian() * sideways, random.nextGaussian() * sideways, 5 + random.nextDouble() * 20));
            radii[b] = 0.01 + random.nextDouble() * 3;
            from[b] = corner(p[b], radii[b], random);
            to[b] = corner(c[b], radii[b], random);
            // A triangle around a point of the segment, across it, much smaller than the radius.
            Vector d = to[b].subtract(from[b]);
            Vector u = d.normalize().perpendicular().scale(radii[b] * 1e-6);
            Vector w = d.normalize().crossProduct(u).normalize().scale(radii[b] * 1e-6);
            Point m = from[b].add(d.scale(0.1 + 0.8 * random.nextDouble()));
            scene.add(new Triangle(m.add(u), m.add(w).subtract(u), m.subtract(w).subtract(u)));
            scene.add(new Sphere(c[b], 0.5)); // something else for the searches to find
        }
        Accelerator bvh = Accelerator.build(scene, true), brute = Accelerator.build(scene, false);
        HitRecord beam = new HitRecord();
        int blocked = 0;
        for (int b = 0; b < beams; b++) {
            bvh.aimShadowBeam(beam, 0, p[b].x, p[b].y, p[b].z, c[b].x, c[b].y, c[b].z, radii[b]);
            Vector d = to[b].subtract(from[b]);
            assertSameAnswer(bvh, brute, new Ray(from[b], d), d.length(), beam);
            if (beam.transmitR == 0) blocked++;
        }
        assertTrue(blocked >= beams * 9 / 10, "the rim rays meet their triangles: " + blocked + " of " + beams);
    }

    private static Point corner(Point centre, double r, Random random) {
        return new Point(
                centre.x + (random.nextBoolean() ? r : -r),
                centre.y + (random.nextBoolean() ? r : -r),
                centre.z + (random.nextBoolean() ? r : -r));
    }

    /**
     * A tree of fewer than {@link ShadowBeam#MIN_PRIMITIVES} primitives gets no beam; one that is a single leaf of
     * that many (a root with primitives of its own) does, straight up an axis too.
     */
    @org.junit.jupiter.api.Test
    void smallTreesHaveNoBeamsAndOneLeafServesThem() {
        Triangle across = new Triangle(new Point(-1, -1, 5), new Point(1, -1, 5), new Point(0, 1, 5));
        HitRecord beam = new HitRecord();
        Accelerator small = Accelerator.build(new Geometries(across), true);
        small.aimShadowBeam(beam, 0, 0, 0, 0, 0, 0, 10, 0.5);
        assertEquals(null, beam.activeBeam, "no beam for a tree of one triangle");

        // Copies of one triangle: no split can separate them, so the root is one leaf.
        Geometries scene = new Geometries(across);
        for (int i = 1; i < ShadowBeam.MIN_PRIMITIVES; i++) {
            scene.add(new Triangle(new Point(-1, -1, 5), new Point(1, -1, 5), new Point(0, 1, 5)));
        }
        Accelerator bvh = Accelerator.build(scene, true, 16, 64), brute = Accelerator.build(scene, false);
        assertTrue(bvh.getBvh().rootCount > 0, "the root is a leaf");
        // Straight up the z axis: the search tilts the central segment, which has no float reciprocals along x and y.
        bvh.aimShadowBeam(beam, 0, 0, 0, 0, 0, 0, 10, 0.5);
        Ray blocked = new Ray(Point.ZERO, new Vector(0.1, 0, 10));
        assertSameAnswer(bvh, brute, blocked, new Vector(0.1, 0, 10).length(), beam);
        assertEquals(0, beam.transmitR, 0, "the triangle blocks the ray");
        assertTrue(beam.activeBeam.collected(), "the beam holds the root leaf");
        Ray passes = new Ray(new Point(0.4, 0.4, 0), new Vector(0, 0.4, 10));
        assertSameAnswer(bvh, brute, passes, new Vector(0, 0.4, 10).length(), beam);
        assertEquals(1, beam.transmitR, 0, "the ray passes beside the triangle");
    }

    @ParameterizedTest(name = "BVH {0}")
    @ValueSource(booleans = {true, false})
    void aNegativeSlotIsRefused(boolean useBvh) {
        Accelerator accelerator = Accelerator.build(new Sphere(Point.ZERO, 1), useBvh);
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class,
                () -> accelerator.aimShadowBeam(new HitRecord(), -1, 0, 0, 5, 0, 0, 10, 1));
        assertTrue(e.getMessage().contains("-1"), e.getMessage());
    }
}
