package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * Tests of the compiled scene: outline edges shared exactly by lone triangles and polygons become watertight,
 * the BVH gives bit-identical answers to brute force, transparent occluders attenuate once per crossing.
 */
class AcceleratorTest {
    private static final Material HALF_TRANSPARENT = new Material().setKt(0.5);

    /** Directions with exact watertight shear (see TriangleTest) plus arbitrary ones. */
    private static final Vector[] DIRECTIONS = {
        new Vector(0, 0, -1),
        new Vector(0, 0, 1),
        new Vector(1, 1, 1),
        new Vector(-1, -2, -2),
        new Vector(2, 1, 2),
        new Vector(0.3, -0.7, 1.1),
        new Vector(-0.0, 0.0, -1),
        new Vector(-0.41, 0.13, -0.9)
    };

    private static Ray through(Point target, Vector d) {
        return new Ray(target.add(d.normalize().scale(-3)), d);
    }

    /**
     * Crossings of a segment, measured through transparency: every crossed surface with kT = 0.5 halves the
     * transmittance, so the exponent is the number of triangles hit (0 = slipped through, 2 = double count).
     */
    private static int crossings(Accelerator accelerator, Ray ray) {
        Double3 t = accelerator.transmittance(ray, 0, 100, new HitRecord());
        assertEquals(t.d1, t.d2);
        int n = (int) Math.round(-Math.log(t.d1) / Math.log(2));
        assertEquals(Math.pow(0.5, n), t.d1, 0, "transmittance is a power of kT");
        return n;
    }

    private static Triangle transparent(Triangle t) {
        t.setMaterial(HALF_TRANSPARENT);
        return t;
    }

    @ParameterizedTest(name = "BVH {0}")
    @ValueSource(booleans = {true, false})
    void sharedEdgeOfTwoLoneTrianglesIsHitExactlyOnce(boolean bvh) {
        // the unit square split along the diagonal (1,0,0) - (0,1,0); test both orientations of the second one
        Point a = new Point(0, 0, 0), b = new Point(1, 0, 0), c = new Point(1, 1, 0), d = new Point(0, 1, 0);
        Triangle t1 = transparent(new Triangle(a, b, d));
        for (Triangle t2 : new Triangle[] {transparent(new Triangle(b, c, d)), transparent(new Triangle(d, c, b))}) {
            Accelerator acc = Accelerator.build(new Geometries(t1, t2), bvh);
            for (double s : new double[] {0.5, 0.25, 0.125, 0.7, 0.9999}) {
                Point onEdge = new Point(1 - s, s, 0);
                for (Vector dir : DIRECTIONS) {
                    Ray ray = through(onEdge, dir);
                    String where = "edge point " + onEdge + " along " + dir;
                    assertEquals(1, crossings(acc, ray), where);
                    HitRecord hit = new HitRecord();
                    assertTrue(acc.intersect(ray, 0, Double.POSITIVE_INFINITY, hit), where);
                    assertTrue(hit.geometry == t1 || hit.geometry == t2, where);
                }
            }
            // the outline of the union stays a boundary: corners and outer edges are misses
            for (Point outline : new Point[] {a, b, c, d, new Point(0.5, 0, 0), new Point(1, 0.5, 0)}) {
                for (Vector dir : new Vector[] {new Vector(0, 0, -1), new Vector(1, 1, 1), new Vector(-1, -2, -2)}) {
                    Ray ray = TriangleTest.through(outline, dir);
                    assertEquals(0, crossings(acc, ray), "outline " + outline + " along " + dir);
                    assertFalse(acc.intersect(ray, 0, Double.POSITIVE_INFINITY, new HitRecord()));
                }
            }
        }
        // each triangle alone keeps the course contract: the (unshared) diagonal is its boundary
        Ray onDiagonal = TriangleTest.through(new Point(0.5, 0.5, 0), new Vector(0, 0, -1));
        assertTrue(t1.findIntersections(onDiagonal).isEmpty());
    }

    @ParameterizedTest(name = "BVH {0}")
    @ValueSource(booleans = {true, false})
    void sharedVertexInsideAFanOfLoneTrianglesIsHitExactlyOnce(boolean bvh) {
        // four lone triangles around the centre (0.5, 0.5, 0) of the unit square, alternately oriented
        Point m = new Point(0.5, 0.5, 0);
        Point[] corners = {new Point(0, 0, 0), new Point(1, 0, 0), new Point(1, 1, 0), new Point(0, 1, 0)};
        Geometries fan = new Geometries();
        for (int i = 0; i < 4; i++) {
            Point p = corners[i], q = corners[(i + 1) % 4];
            fan.add(transparent(i % 2 == 0 ? new Triangle(m, p, q) : new Triangle(q, p, m)));
        }
        Accelerator acc = Accelerator.build(fan, bvh);
        for (Vector dir : DIRECTIONS) {
            assertEquals(1, crossings(acc, through(m, dir)), "centre along " + dir);
            for (Point corner : corners) {
                // the spokes from the centre to the corners are shared edges too
                Point spoke = new Point((m.x + corner.x) / 2, (m.y + corner.y) / 2, 0);
                assertEquals(1, crossings(acc, through(spoke, dir)), "spoke " + spoke + " along " + dir);
            }
        }
    }

    @ParameterizedTest(name = "BVH {0}")
    @ValueSource(booleans = {true, false})
    void edgeSharedByAPolygonAndATriangleIsHitExactlyOnce(boolean bvh) {
        Polygon square = new Polygon(new Point(0, 0, 0), new Point(1, 0, 0), new Point(1, 1, 0), new Point(0, 1, 0));
        square.setMaterial(HALF_TRANSPARENT);
        Triangle ear = transparent(new Triangle(new Point(1, 1, 0), new Point(1, 0, 0), new Point(2, 0.5, 0)));
        Accelerator acc = Accelerator.build(new Geometries(square, new Geometries(ear)), bvh);
        for (double y : new double[] {0.5, 0.25, 0.8}) {
            for (Vector dir : DIRECTIONS) {
                assertEquals(1, crossings(acc, through(new Point(1, y, 0), dir)), "x = 1, y = " + y + " along " + dir);
            }
        }
        // the polygon's own diagonal: still one
        assertEquals(1, crossings(acc, through(new Point(0.5, 0.5, 0), new Vector(0.3, 0.2, 1))));
    }

    @Test
    void edgesThatOnlyOverlapPartlyAreNotShared() {
        // the second triangle's edge covers only half of the first's: nothing is shared, boundaries stay open
        Triangle t1 = transparent(new Triangle(new Point(0, 0, 0), new Point(2, 0, 0), new Point(0, 2, 0)));
        Triangle t2 = transparent(new Triangle(new Point(2, 0, 0), new Point(1, 1, 0), new Point(2, 2, 0)));
        Accelerator acc = Accelerator.build(new Geometries(t1, t2), false);
        assertEquals(0, crossings(acc, TriangleTest.through(new Point(1.5, 0.5, 0), new Vector(0, 0, 1))));
    }

    // ---------------------------------------------------------------- BVH == brute force

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 6).mapToObj(i -> Arguments.of(0xB0BL + 977L * i));
    }

    /** A random scene of spheres, triangles, polygons, cylinders, a mesh, a plane and a tube; some transparent. */
    static Geometries randomScene(Random random, int count) {
        Geometries scene = new Geometries();
        Geometries nested = new Geometries();
        for (int i = 0; i < count; i++) {
            Point c = new Point(random.nextGaussian() * 10, random.nextGaussian() * 10, random.nextGaussian() * 10);
            Geometry g = switch (random.nextInt(5)) {
                case 0 -> new Sphere(c, 0.2 + random.nextDouble() * 2);
                case 1 ->
                    new Triangle(
                            c,
                            c.add(SurfaceStartProperty.randomUnit(random).scale(1 + 2 * random.nextDouble())),
                            c.add(SurfaceStartProperty.randomUnit(random).scale(1 + 2 * random.nextDouble())));
                case 2 -> {
                    Vector n = SurfaceStartProperty.randomUnit(random);
                    Vector u = n.perpendicular(), w = n.crossProduct(u);
                    double s = 0.5 + 2 * random.nextDouble();
                    yield new Polygon(c.add(u.scale(s)), c.add(w.scale(s)), c.add(u.scale(-s)), c.add(w.scale(-s)));
                }
                case 3 ->
                    new Cylinder(
                            0.3 + random.nextDouble(),
                            new Ray(c, SurfaceStartProperty.randomUnit(random)),
                            0.5 + 3 * random.nextDouble());
                default -> {
                    double[] v = MeshTest.transformed(MeshTest.OCTAHEDRON_VERTICES, random);
                    for (int k = 0; k < v.length; k++) v[k] = v[k] * 0.02 + (k % 3 == 0 ? c.x : k % 3 == 1 ? c.y : c.z);
                    yield new Mesh(v, MeshTest.OCTAHEDRON_FACES);
                }
            };
            if (random.nextInt(4) == 0) g.setMaterial(new Material().setKt(0.3 + 0.5 * random.nextDouble()));
            if (random.nextBoolean()) scene.add(g);
            else nested.add(g);
        }
        scene.add(nested);
        scene.add(new Plane(new Point(0, 0, -30), new Vector(0.1, 0.2, 1)));
        scene.add(new Tube(0.5, new Ray(new Point(30, 0, 0), new Vector(0.1, 1, 0.3))));
        return scene;
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void bvhAndBruteForceGiveIdenticalAnswers(long seed) {
        Random random = new Random(seed);
        Geometries scene = randomScene(random, 150);
        Accelerator bvh = Accelerator.build(scene, true);
        Accelerator brute = Accelerator.build(scene, false);
        Accelerator smallLeaves = Accelerator.build(scene, true, 2, 1);
        assertNotNull(bvh.getBvh());
        assertNull(brute.getBvh());
        assertEquals(brute.boundedPrimitiveCount(), bvh.boundedPrimitiveCount());
        assertEquals(2, bvh.unboundedPrimitiveCount());
        int hits = 0;
        for (int i = 0; i < 800; i++) {
            Point o = new Point(random.nextGaussian() * 25, random.nextGaussian() * 25, random.nextGaussian() * 25);
            Vector d = SurfaceStartProperty.randomUnit(random);
            if (i % 10 == 0) d = new Vector(random.nextBoolean() ? -0.0 : 0.0, 0.0, random.nextBoolean() ? 1 : -1);
            Ray ray = new Ray(o, d);
            String where = "seed " + seed + " ray " + i + " " + ray;
            HitRecord a = new HitRecord(), b = new HitRecord(), c = new HitRecord(), direct = new HitRecord();
            boolean hitA = bvh.intersect(ray, 0, Double.POSITIVE_INFINITY, a);
            boolean hitB = brute.intersect(ray, 0, Double.POSITIVE_INFINITY, b);
            boolean hitC = smallLeaves.intersect(ray, 0, Double.POSITIVE_INFINITY, c);
            // the uncompiled composite is an independent reference for the distance
            boolean hitD = scene.intersect(ray, 0, Double.POSITIVE_INFINITY, direct);
            assertEquals(hitB, hitA, where);
            assertEquals(hitB, hitC, where);
            assertEquals(hitD, hitB, where);
            if (hitA) {
                hits++;
                assertEquals(b.t, a.t, 0, where);
                assertEquals(b.t, c.t, 0, where);
                assertSame(b.geometry, a.geometry, where);
                assertEquals(b.part, a.part, where);
                assertSame(b.geometry, c.geometry, where);
                assertEquals(direct.t, b.t, 1e-12 * Math.max(1, b.t), where);
            }
            double tMax = 5 + random.nextDouble() * 50;
            assertEquals(
                    brute.occludes(ray, 0, tMax, new HitRecord()), bvh.occludes(ray, 0, tMax, new HitRecord()), where);
            assertEquals(
                    brute.transmittance(ray, 0, tMax, new HitRecord()),
                    bvh.transmittance(ray, 0, tMax, new HitRecord()),
                    where);
        }
        assertTrue(hits > 80, "the scene should be hit by a fair share of rays: " + hits);
    }

    @ParameterizedTest(name = "BVH {0}")
    @ValueSource(booleans = {true, false})
    void equalDistanceHitsGoToTheGeometryAddedFirst(boolean bvh) {
        // three identical spheres and two identical triangles: the first added wins, whatever the tree order
        List<Geometry> spheres = new ArrayList<>();
        Geometries scene = new Geometries();
        for (int i = 0; i < 3; i++) {
            Sphere s = new Sphere(new Point(0, 0, 0), 1);
            spheres.add(s);
        }
        Triangle t1 = new Triangle(new Point(-5, -5, 3), new Point(5, -5, 3), new Point(0, 5, 3));
        Triangle t2 = new Triangle(new Point(-5, -5, 3), new Point(5, -5, 3), new Point(0, 5, 3));
        scene.add(t1, spheres.get(0), new Geometries(spheres.get(1), t2), spheres.get(2));
        for (int k = 0; k < 40; k++) scene.add(new Sphere(new Point(20 + k, 20, 20), 0.5)); // make a real tree
        Accelerator acc = Accelerator.build(scene, bvh);
        HitRecord hit = new HitRecord();
        assertTrue(acc.intersect(Hits.ray(0.1, 0.2, -10, 0, 0, 1), 0, Double.POSITIVE_INFINITY, hit));
        assertSame(spheres.get(0), hit.geometry);
        assertTrue(acc.intersect(Hits.ray(0.1, 0.2, 10, 0, 0, -1), 0, Double.POSITIVE_INFINITY, hit.reset()));
        assertSame(t1, hit.geometry);
    }

    @Test
    void transparentOccludersMultiplyTheirTransmittance() {
        Sphere glass = new Sphere(new Point(0, 0, 5), 1);
        glass.setMaterial(new Material().setKt(new Double3(0.5, 0.8, 1)));
        Triangle tinted = new Triangle(new Point(-2, -2, 8), new Point(2, -2, 8), new Point(0, 2, 8));
        tinted.setMaterial(new Material().setKt(0.25));
        Sphere opaque = new Sphere(new Point(0, 0, 12), 1);
        for (boolean bvh : new boolean[] {true, false}) {
            Accelerator acc = Accelerator.build(new Geometries(glass, tinted, opaque), bvh);
            Ray up = Hits.ray(0, 0, 0, 0, 0, 1);
            // the sphere is crossed twice (in and out), the triangle once
            Double3 through = acc.transmittance(up, 0, 10, new HitRecord());
            assertEquals(0.5 * 0.5 * 0.25, through.d1, 1e-15);
            assertEquals(0.8 * 0.8 * 0.25, through.d2, 1e-15);
            assertEquals(0.25, through.d3, 1e-15);
            // up to the sphere only: one crossing
            assertEquals(new Double3(0.5, 0.8, 1), acc.transmittance(up, 0, 5, new HitRecord()));
            // an opaque occluder blocks completely
            assertEquals(Double3.ZERO, acc.transmittance(up, 0, 20, new HitRecord()));
            assertTrue(acc.occludes(up, 0, 20, new HitRecord()));
            // nothing in the way
            assertEquals(Double3.ONE, acc.transmittance(up, 0, 3.9, new HitRecord()));
            assertFalse(acc.occludes(up, 0, 3.9, new HitRecord()));
            assertEquals(Double3.ONE, acc.transmittance(Hits.ray(5, 5, 0, 0, 0, 1), 0, 100, new HitRecord()));
        }
    }

    @Test
    void theOccluderCacheRemembersTheBlockerAndTestsItFirst() {
        // Many small opaque triangles along the ray's way, one big one that blocks it.
        Geometries scene = new Geometries();
        for (int i = 0; i < 50; i++) {
            scene.add(new Triangle(new Point(i, 3, 1), new Point(i + 0.5, 3, 1), new Point(i, 3.5, 1)));
        }
        Triangle blocker = new Triangle(new Point(-5, -5, 6), new Point(5, -5, 6), new Point(0, 5, 6));
        scene.add(blocker);
        Sphere glass = new Sphere(new Point(0, 0, 3), 1);
        glass.setMaterial(new Material().setKt(0.5));
        scene.add(glass);
        for (boolean bvh : new boolean[] {true, false}) {
            Accelerator acc = Accelerator.build(scene, bvh);
            Ray up = Hits.ray(0.1, 0.1, 0, 0, 0, 1);
            HitRecord shadow = new HitRecord();
            assertFalse(acc.passesLight(up, 0, 10, shadow));
            int slot = shadow.occluder;
            assertTrue(slot >= 0, "the blocking triangle's slot is reported");
            shadow.occluderHint = slot;
            long before = shadow.primitiveTests;
            assertFalse(acc.passesLight(up, 0, 10, shadow));
            assertEquals(1, shadow.primitiveTests - before, "the hinted occluder alone settles the query");
            assertEquals(slot, shadow.occluder);
            // Short of the blocker: the hint misses, the glass sphere attenuates, nothing is reported.
            assertTrue(acc.passesLight(up, 0, 5, shadow));
            assertEquals(-1, shadow.occluder);
            assertEquals(0.25, shadow.transmitR);
        }
    }

    /**
     * {@link HitRecord#leaveSurface}: shadow queries leave out the flat surface their segments start on: a polygon
     * whole, a plane, one triangle of a mesh (its neighbours still block), nothing for a sphere or null. The segments
     * here cross the surface on purpose (a renderer's never do), so that leaving it out shows; tree, brute force and
     * a beam agree.
     */
    @Test
    void shadowQueriesLeaveOutTheFlatSurfaceTheyStartOn() {
        Polygon square =
                new Polygon(new Point(-1, -1, 1), new Point(1, -1, 1), new Point(1, 1, 1), new Point(-1, 1, 1));
        // A mesh of two triangles over the unit square at z = 2 (part 0 holds x > y, part 1 the rest).
        Mesh roof = new Mesh(new double[] {0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2}, new int[] {0, 1, 2, 0, 2, 3});
        Plane floor = new Plane(new Point(0, 0, 3), Vector.AXIS_Z);
        Sphere ball = new Sphere(new Point(5, 5, 1), 0.5);
        Geometries scene = new Geometries(square, roof, floor, ball);
        // Enough small triangles far away for the scene to get beams.
        for (int i = 0; i < 70; i++) {
            scene.add(new Triangle(new Point(50 + i, 50, 0), new Point(50.5 + i, 50, 0), new Point(50 + i, 50.5, 0)));
        }
        Ray throughSquare = Hits.ray(0.1, 0.1, 0, 0, 0, 1); // the square at t = 1
        Ray throughRoofPart0 = Hits.ray(0.7, 0.2, 1.5, 0, 0, 1); // the roof's part 0 at t = 0.5
        Ray throughRoofPart1 = Hits.ray(0.2, 0.7, 1.5, 0, 0, 1); // the roof's part 1 at t = 0.5
        Ray throughFloor = Hits.ray(3, 3, 2.5, 0, 0, 1); // the plane at t = 0.5
        Ray throughBall = Hits.ray(5, 5, 0, 0, 0, 1); // the sphere at t = 0.5
        for (boolean bvh : new boolean[] {true, false}) {
            Accelerator acc = Accelerator.build(scene, bvh);
            HitRecord shadow = new HitRecord();
            assertFalse(acc.passesLight(throughSquare, 0, 1.5, shadow), "nothing left out yet");
            shadow.leaveSurface(square, 0);
            assertTrue(acc.passesLight(throughSquare, 0, 1.5, shadow), "the square left out");
            shadow.leaveSurface(roof, 0);
            assertTrue(acc.passesLight(throughRoofPart0, 0, 0.9, shadow), "the roof's part 0 left out");
            assertFalse(acc.passesLight(throughRoofPart1, 0, 0.9, shadow), "its other triangle still blocks");
            shadow.leaveSurface(floor, 0);
            assertTrue(acc.passesLight(throughFloor, 0, 1, shadow), "the plane left out");
            shadow.leaveSurface(ball, 0);
            assertFalse(acc.passesLight(throughBall, 0, 1, shadow), "a sphere is not flat: never left out");
            shadow.leaveSurface(null, 0);
            assertFalse(acc.passesLight(throughSquare, 0, 1.5, shadow), "null leaves out nothing");
            // Through a beam aimed along the segment: the same answers.
            shadow.leaveSurface(square, 0);
            acc.aimShadowBeam(shadow, 0, 0.1, 0.1, 0, 0.1, 0.1, 1.5, 0.25);
            assertTrue(acc.passesLight(throughSquare, 0, 1.5, shadow), "the square left out within the beam");
            if (bvh)
                assertTrue(
                        shadow.activeBeam != null && shadow.activeBeam.collected(), "the query went through the beam");
            shadow.leaveSurface(null, 0);
            assertFalse(acc.passesLight(throughSquare, 0, 1.5, shadow), "and tested within it otherwise");
        }
    }

    @Test
    void emptyAndUnboundedScenes() {
        Accelerator empty = Accelerator.build(new Geometries(), true);
        assertFalse(empty.intersect(Hits.ray(0, 0, 0, 1, 0, 0), 0, Double.POSITIVE_INFINITY, new HitRecord()));
        assertNull(empty.getBoundingBox());
        assertEquals(0, empty.boundedPrimitiveCount());
        Accelerator planeOnly = Accelerator.build(new Geometries(new Plane(Point.ZERO, Vector.AXIS_Z)), true);
        assertNull(planeOnly.getBvh());
        HitRecord hit = new HitRecord();
        assertTrue(planeOnly.intersect(Hits.ray(0, 0, 2, 0, 0, -1), 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(2, hit.t);
        Accelerator bounded = Accelerator.build(new Sphere(new Point(1, 2, 3), 1), true);
        assertTrue(bounded.getBoundingBox().contains(new Point(2, 2, 3)));
    }

    /**
     * A clear surface (kT exactly 1) is skipped by shadow queries without changing their answer: light passes with
     * transmittance exactly 1 and without a primitive test, while occludes() (any surface) still sees it; a sphere
     * of kT 0.5 crossed twice still gives 0.25.
     */
    @ParameterizedTest
    @ValueSource(booleans = {true, false})
    void clearSurfacesAreSkippedByShadowQueries(boolean useBvh) {
        Sphere clear = new Sphere(new Point(0, 0, 5), 1);
        clear.setMaterial(new Material().setKt(1));
        Sphere half = new Sphere(new Point(0, 0, 10), 1);
        half.setMaterial(new Material().setKt(0.5));
        Ray ray = new Ray(Point.ZERO, new Vector(0, 0, 1));
        Accelerator onlyClear = Accelerator.build(new Geometries(clear), useBvh);
        HitRecord scratch = new HitRecord();
        assertTrue(onlyClear.passesLight(ray, 0, 20, scratch));
        assertEquals(1.0, scratch.transmitR, 0);
        assertEquals(0, scratch.primitiveTests, "the clear sphere is not even tested");
        assertTrue(onlyClear.occludes(ray, 0, 20, new HitRecord()), "but it is a surface in the way");
        Accelerator both = Accelerator.build(new Geometries(clear, half), useBvh);
        assertTrue(both.passesLight(ray, 0, 20, scratch));
        assertEquals(0.25, scratch.transmitG, 0);
    }

    /**
     * Clear surfaces get a subtree of their own under the BVH's root, which shadow queries leave out: on random
     * scenes of opaque triangles, tinted and clear spheres, every shadow query, occlusion query and closest hit
     * through the BVH equals the brute-force scan bit for bit, and the clear subtree is there to be skipped.
     */
    @ParameterizedTest
    @ValueSource(longs = {11, 12, 13})
    void shadowQueriesSkipTheClearSubtreeWithTheSameAnswers(long seed) {
        java.util.Random random = new java.util.Random(seed);
        Geometries scene = new Geometries();
        for (int i = 0; i < 300; i++) {
            Point a = new Point(random.nextGaussian() * 20, random.nextGaussian() * 20, random.nextGaussian() * 20);
            Point b = a.add(new Vector(random.nextDouble() * 3 + 0.1, random.nextDouble(), 0));
            Point c = a.add(new Vector(0, random.nextDouble() * 3 + 0.1, random.nextDouble()));
            scene.add(new Triangle(a, b, c));
            if (i % 3 == 0) {
                Sphere sphere = new Sphere(a.add(new Vector(0, 0, 4)), random.nextDouble() * 2 + 0.5);
                sphere.setMaterial(new Material().setKt(i % 2 == 0 ? 1 : 0.7));
                scene.add(sphere);
            }
        }
        Accelerator bvh = Accelerator.build(scene, true), brute = Accelerator.build(scene, false);
        assertTrue(bvh.getBvh().secondGroupSlots != 0, "the clear spheres have root slots of their own");
        HitRecord withBvh = new HitRecord(), without = new HitRecord();
        for (int i = 0; i < 3000; i++) {
            Point from = new Point(random.nextGaussian() * 25, random.nextGaussian() * 25, random.nextGaussian() * 25);
            Vector to = new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            Ray ray = new Ray(from, to);
            double length = random.nextDouble() * 60;
            boolean passes = bvh.passesLight(ray, 0, length, withBvh);
            assertEquals(brute.passesLight(ray, 0, length, without), passes, "shadow ray " + i);
            assertEquals(without.transmitR, withBvh.transmitR, 0, "transmittance of shadow ray " + i);
            assertEquals(without.transmitB, withBvh.transmitB, 0, "transmittance of shadow ray " + i);
            assertEquals(brute.occludes(ray, 0, length, without), bvh.occludes(ray, 0, length, withBvh));
            boolean hit = bvh.intersect(ray, 0, length, withBvh.reset());
            assertEquals(brute.intersect(ray, 0, length, without.reset()), hit, "closest hit of ray " + i);
            if (hit) assertEquals(without.t, withBvh.t, 0);
        }
    }

    /**
     * The clear subtree is left out at the root, not only its leaves: a shadow ray that crosses nothing but clear
     * spheres tests the root's child boxes and nothing below them (the opaque triangles lie beyond its end).
     */
    @Test
    void aShadowRayThroughClearSurfacesOnlyStopsAtTheRoot() {
        Geometries scene = new Geometries();
        for (int i = 0; i < 50; i++) {
            double y = i - 25;
            scene.add(new Triangle(new Point(100, y, 0), new Point(101, y + 1, 0), new Point(100, y, 1)));
        }
        for (int i = 0; i < 30; i++) {
            Sphere sphere = new Sphere(new Point(i * 0.5, (i % 3) - 1, 0), 0.4);
            sphere.setMaterial(new Material().setKt(1));
            scene.add(sphere);
        }
        Accelerator accelerator = Accelerator.build(scene, true);
        HitRecord scratch = new HitRecord();
        assertTrue(accelerator.passesLight(new Ray(new Point(-5, 0, 0), new Vector(1, 0, 0)), 0, 20, scratch));
        assertEquals(1 + BVH.WIDTH, scratch.nodeVisits, "the root's child boxes only");
        assertEquals(0, scratch.primitiveTests);
        HitRecord any = new HitRecord();
        assertTrue(accelerator.occludes(new Ray(new Point(-5, 0, 0), new Vector(1, 0, 0)), 0, 20, any));
        assertTrue(any.nodeVisits > 1 + BVH.WIDTH, "an occlusion query still searches the clear spheres");
    }
}
