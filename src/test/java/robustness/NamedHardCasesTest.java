package robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Accelerator;
import geometries.BoundingBox;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.HitRecord;
import geometries.Mesh;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.Tube;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Optics;
import renderer.sampling.SampleStream;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.SuperSamplingBlackboard;
import renderer.sampling.TargetShape;

/** The hard cases of textbook ray tracers, each by name, each with what it guards against. */
class NamedHardCasesTest {

    private static boolean hits(geometries.Intersectable g, Ray ray) {
        return g.intersect(ray, 0, Double.POSITIVE_INFINITY, new HitRecord());
    }

    /** Grazing and tangent rays: the hit/miss classification flips exactly once across tangency. */
    @ParameterizedTest
    @ValueSource(doubles = {0, 1e3, 1e6})
    void tangencyIsClassifiedConsistentlyOnBothSides(double distance) {
        Point c = new Point(distance, distance, 0);
        Sphere sphere = new Sphere(c, 1);
        double top = c.y + 1;
        // Rays along +x at heights stepping down through the tangent height, ulp by ulp.
        double y = top;
        for (int i = 0; i < 64; i++) y = Math.nextUp(y);
        boolean seenHit = false;
        int flips = 0;
        for (int i = 0; i < 200_000 && y > c.y; i++) {
            boolean hit = hits(sphere, new Ray(new Point(c.x - 10, y, 0), Vector.AXIS_X));
            if (hit != seenHit) {
                flips++;
                seenHit = hit;
            }
            if (y > top) assertFalse(hit, "above the tangent at " + y);
            y = i < 1000 ? Math.nextDown(y) : y - (top - c.y) * 1e-5;
        }
        assertEquals(1, flips, "the classification flips once, from miss to hit");
        assertTrue(seenHit);
    }

    @Test
    void aTangentRayTouchesButDoesNotHit() {
        assertFalse(hits(new Sphere(Point.ZERO, 1), new Ray(new Point(-5, 1, 0), Vector.AXIS_X)));
        assertFalse(hits(new Tube(1, new Ray(Point.ZERO, Vector.AXIS_Z)), new Ray(new Point(-5, 1, 3), Vector.AXIS_X)));
    }

    /** Parallel rays, with exact and negative zeros in the direction: never a hit, never a NaN. */
    @Test
    void raysParallelToPlanesAndAxesMiss() {
        Plane plane = new Plane(Point.ZERO, Vector.AXIS_Z);
        for (Vector d : List.of(new Vector(1, 0, 0), new Vector(1, 0, -0.0), new Vector(-0.0, 1, 0.0))) {
            assertFalse(hits(plane, new Ray(new Point(0, 0, 1), d)), "above the plane along " + d);
            assertFalse(hits(plane, new Ray(new Point(0, 0, 0), d)), "inside the plane along " + d);
        }
        Tube tube = new Tube(1, new Ray(Point.ZERO, Vector.AXIS_Z));
        for (Vector d : List.of(new Vector(0, 0, 1), new Vector(-0.0, 0.0, -1), new Vector(0.0, -0.0, 1))) {
            assertFalse(hits(tube, new Ray(new Point(0.5, 0, 0), d)), "inside the tube along " + d);
            assertFalse(hits(tube, new Ray(new Point(3, 0, 0), d)), "outside the tube along " + d);
            assertFalse(hits(tube, new Ray(new Point(1, 0, 0), d)), "on the tube along " + d);
        }
        Cylinder cylinder = new Cylinder(1, new Ray(Point.ZERO, Vector.AXIS_Z), 2);
        HitRecord hit = new HitRecord();
        assertTrue(cylinder.intersect(new Ray(new Point(0.5, -0.0, -1), new Vector(0, -0.0, 1)), 0, 100, hit));
        assertEquals(1, hit.t, 1e-15, "parallel to the axis inside: the bottom cap at t = 1");
        assertFalse(hits(cylinder, new Ray(new Point(1.5, 0, -1), new Vector(-0.0, 0, 1))));
        BoundingBox box = new BoundingBox(0, 0, 0, 1, 1, 1);
        assertTrue(box.intersects(new Ray(new Point(0.5, 0.5, -1), new Vector(-0.0, 0.0, 1)), 0, 10));
        assertTrue(box.intersects(new Ray(new Point(0, 0.5, -1), new Vector(0.0, -0.0, 1)), 0, 10), "in a face plane");
        assertFalse(box.intersects(new Ray(new Point(2, 0.5, -1), new Vector(-0.0, 0, 1)), 0, 10));
    }

    /** Rays starting on a surface do not hit it at t = 0; leaving inward they find the far side. */
    @Test
    void raysStartingOnASurface() {
        Sphere sphere = new Sphere(Point.ZERO, 1);
        assertFalse(hits(sphere, new Ray(new Point(1, 0, 0), new Vector(1, 1, 0))), "outward");
        HitRecord hit = new HitRecord();
        assertTrue(sphere.intersect(new Ray(new Point(1, 0, 0), new Vector(-1, 0, 0)), 0, 10, hit));
        assertEquals(2, hit.t, 1e-15, "inward: the far side");
        assertFalse(hits(new Plane(Point.ZERO, Vector.AXIS_Z), new Ray(new Point(3, 4, 0), new Vector(1, 1, 1))));
        Triangle t = new Triangle(new Point(0, 0, 0), new Point(1, 0, 0), new Point(0, 1, 0));
        assertFalse(hits(t, new Ray(new Point(0.2, 0.2, 0), new Vector(0, 0, 1))));
    }

    /**
     * Rays exactly through box corners and edges: a grid of unit squares (meshed, so edges are shared) is hit by
     * every ray aimed exactly at its vertices and edge midpoints, with the BVH exactly as by brute force.
     */
    @Test
    void raysThroughBoxCornersAndEdgesOfAGrid() {
        int n = 8;
        double[] vertices = new double[3 * (n + 1) * (n + 1)];
        int[] indices = new int[6 * n * n];
        for (int j = 0, v = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++, v++) {
                vertices[3 * v] = i;
                vertices[3 * v + 1] = j;
            }
        }
        for (int j = 0, t = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                indices[t++] = a;
                indices[t++] = b;
                indices[t++] = d;
                indices[t++] = a;
                indices[t++] = d;
                indices[t++] = c;
            }
        }
        Geometries grid = new Geometries(new Mesh(vertices, indices));
        Accelerator bvh = Accelerator.build(grid, true, 16, 1);
        Accelerator brute = Accelerator.build(grid, false);
        for (int j = 1; j < 2 * n; j++) {
            for (int i = 1; i < 2 * n; i++) {
                Point target = new Point(i / 2.0, j / 2.0, 0);
                for (Point eye : List.of(new Point(4, 4, 10), new Point(i / 2.0, j / 2.0, 5), new Point(-3, 11, 2))) {
                    Ray ray = new Ray(eye, target.subtract(eye));
                    HitRecord a = new HitRecord(), b = new HitRecord();
                    assertTrue(bvh.intersect(ray, 0, 100, a), "leak through " + target + " from " + eye);
                    assertTrue(brute.intersect(ray, 0, 100, b));
                    assertEquals(b.t, a.t, 0.0);
                    assertEquals(b.part, a.part);
                }
            }
        }
    }

    @Test
    void degenerateTrianglesAndPolygonsAreRejectedWithAClearMessage() {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class,
                () -> new Triangle(new Point(0, 0, 0), new Point(1, 1, 1), new Point(2, 2, 2)));
        assertTrue(e.getMessage().contains("collinear"), e.getMessage());
        e = assertThrows(
                IllegalArgumentException.class,
                () -> new Polygon(new Point(0, 0, 0), new Point(1, 0, 0), new Point(1, 0, 0), new Point(0, 1, 0)));
        assertTrue(e.getMessage().contains("coincide"), e.getMessage());
        // In a mesh, zero-area triangles are kept out of the tree and never produce a NaN.
        Mesh mesh = new Mesh(new double[] {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0}, new int[] {0, 1, 2, 0, 1, 3});
        Accelerator a = Accelerator.build(new Geometries(mesh), true);
        assertEquals(1, a.boundedPrimitiveCount());
        HitRecord hit = new HitRecord();
        assertTrue(a.intersect(new Ray(new Point(0.2, 0.2, 1), new Vector(0, 0, -1)), 0, 10, hit));
        assertEquals(1, hit.part);
    }

    /**
     * Nearly collinear vertices: within the shape tolerance (1e-9 of the size) a vertex counts as lying on the side
     * and is rejected by name (its fan triangle would have no area); a vertex bulging out by 1e-6 is a valid convex
     * polygon with a stable normal and exact hits on both sides of the bulge.
     */
    @Test
    void nearlyCollinearPolygonVertices() {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class,
                () -> new Polygon(
                        new Point(0, 0, 0),
                        new Point(1, 0, 0),
                        new Point(2, -1e-12, 0),
                        new Point(3, 0, 0),
                        new Point(3, 1, 0),
                        new Point(0, 1, 0)));
        assertTrue(e.getMessage().contains("lies on the side"), e.getMessage());
        Polygon p = new Polygon(
                new Point(0, 0, 0),
                new Point(1, -1e-6, 0),
                new Point(2, -1e-6, 0),
                new Point(3, 0, 0),
                new Point(3, 1, 0),
                new Point(0, 1, 0));
        Vector n = p.getNormal(Point.ZERO);
        assertEquals(1, Math.abs(n.z), 1e-15);
        assertTrue(hits(p, new Ray(new Point(1.5, -0.9e-6, 1), new Vector(0, 0, -1))), "inside the bulge");
        assertFalse(hits(p, new Ray(new Point(1.5, -1.1e-6, 1), new Vector(0, 0, -1))), "just outside it");
    }

    /** Total internal reflection exactly at the critical angle, and just inside it: no NaN, the right branch. */
    @Test
    void totalInternalReflectionAtTheCriticalAngle() {
        double ior = 1.5;
        double critical = Math.asin(1 / ior);
        Vector n = Vector.AXIS_Z; // outward; the ray travels inside the glass toward +z
        for (double angle : new double[] {Math.nextDown(critical), critical, Math.nextUp(critical), 1.2, 0.3}) {
            Vector v = new Vector(Math.sin(angle), 0, Math.cos(angle));
            Vector out = Optics.refract(v, n, v.dotProduct(n), ior);
            assertTrue(Double.isFinite(out.x) && Double.isFinite(out.z), "finite at " + angle);
            assertEquals(1, out.length(), 1e-12);
            if (Optics.isTotallyReflected(v, n, ior)) {
                assertTrue(out.z < 0, "reflected back inside at " + angle);
            } else {
                assertTrue(out.z >= 0, "refracted out at " + angle);
                assertEquals(ior * Math.sin(angle), Math.hypot(out.x, out.y), 1e-9, "Snell's law at " + angle);
            }
        }
        Vector atCritical = new Vector(Math.sin(Math.nextUp(critical)), 0, Math.cos(Math.nextUp(critical)));
        assertTrue(Optics.isTotallyReflected(atCritical, n, ior));
    }

    @Test
    void normalizationOfExtremeVectors() {
        double third = 1 / Math.sqrt(3);
        for (double s : new double[] {1e-200, 1e200, Double.MIN_VALUE, Double.MAX_VALUE, 1e-308}) {
            Vector v = new Vector(s, s, s).normalize();
            assertEquals(third, v.x, 1e-15, "scale " + s);
            assertEquals(third, v.y, 1e-15);
            assertEquals(third, v.z, 1e-15);
        }
        assertEquals(1, new Vector(Double.MIN_VALUE, 0, 0).normalize().x);
        assertEquals(
                1,
                new Vector(0, -Double.MAX_VALUE, Double.MAX_VALUE).normalize().length(),
                1e-15);
    }

    /** With one sample, a light's disk is sampled exactly at its centre: the hard-shadow ray. */
    @Test
    void lightSamplingAtTheCentreOfTheDisk() {
        for (SamplingPattern pattern : SamplingPattern.values()) {
            double[] o = SuperSamplingBlackboard.getSampleOffsets(
                    new SamplingConfig(1, TargetShape.CIRCLE, pattern), new SampleStream(3));
            assertEquals(0.0, o[0]);
            assertEquals(0.0, o[1]);
        }
        double[] probes = new double[18];
        SuperSamplingBlackboard.getProbeOffsets(9, new SampleStream(5), probes);
        assertEquals(0.0, probes[0], "the first adaptive probe is the centre");
        assertEquals(0.0, probes[1]);
    }
}
