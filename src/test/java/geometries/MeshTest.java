package geometries;

import static geometries.Hits.assertRejected;
import static geometries.Hits.assertVector;
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
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link Mesh}: validation, normals, and watertightness: every edge and vertex of a mesh is shared,
 * so a ray through one is claimed by exactly one of the triangles around it.
 */
class MeshTest {
    /** The octahedron |x| + |y| + |z| = 1: vertices on the axes, faces wound outward. */
    static final double[] OCTAHEDRON_VERTICES = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};

    static final int[] OCTAHEDRON_FACES = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

    private final Mesh octahedron = new Mesh(OCTAHEDRON_VERTICES, OCTAHEDRON_FACES);

    @Test
    void badInputIsRejectedNamingTheValue() {
        assertRejected(() -> new Mesh(new double[] {0, 0, 0, 1}, new int[] {0, 0, 0}), "multiple of 3", "4");
        assertRejected(() -> new Mesh(new double[] {0, 0, 0}, new int[] {}), "indices", "0");
        assertRejected(() -> new Mesh(new double[] {0, 0, 0}, new int[] {0, 0}), "indices", "2");
        assertRejected(
                () -> new Mesh(new double[] {0, 0, 0, 1, Double.NaN, 0, 0, 1, 0}, new int[] {0, 1, 2}),
                "vertex 1",
                "NaN");
        assertRejected(
                () -> new Mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 3}), "triangle 0", "3");
        assertRejected(
                () -> new Mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2, 0, -1, 2}),
                "triangle 1",
                "-1");
        assertRejected(
                () -> new Mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2}, new double[] {0, 0, 1}),
                "normals",
                "9");
        assertRejected(
                () -> new Mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2}, new double[] {
                    0, 0, 1, 0, 0, 0, 0, 0, 1
                }),
                "normal 1");
        assertRejected(() -> new Mesh(null, new int[] {0, 1, 2}), "vertices");
        assertRejected(() -> new Mesh(new double[9], null), "indices");
    }

    @Test
    void inputArraysAreCopied() {
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        int[] i = {0, 1, 2};
        Mesh m = new Mesh(v, i);
        v[3] = 100;
        i[1] = 0;
        assertEquals(new Point(1, 0, 0), m.vertex(1));
        assertFalse(m.isDegenerate(0));
    }

    @Test
    void countsBoxAndDegenerateTriangles() {
        assertEquals(8, octahedron.triangleCount());
        assertEquals(6, octahedron.vertexCount());
        assertEquals(new BoundingBox(-1, -1, -1, 1, 1, 1), octahedron.getBoundingBox());
        // a zero-area triangle is kept but never hit
        Mesh withSliver = new Mesh(new double[] {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0}, new int[] {0, 1, 2, 0, 1, 3});
        assertTrue(withSliver.isDegenerate(0));
        assertFalse(withSliver.isDegenerate(1));
        // (1.5, 0, 0) lies only on the zero-area triangle
        assertTrue(withSliver.findIntersections(Hits.ray(1.5, 0, -1, 0, 0, 1)).isEmpty(), "on the sliver only");
        assertTrue(withSliver.findIntersections(Hits.ray(1.5, 0, -1, 0, 0.1, 1)).isEmpty(), "on the sliver only");
        Hits.assertPoints(
                withSliver.findIntersections(Hits.ray(0.25, 0.25, -1, 0, 0, 1)),
                1e-15,
                "inside",
                new Point(0.25, 0.25, 0));
    }

    @Test
    void normals() {
        double s = 1 / Math.sqrt(3);
        // getNormal picks the face whose plane the point lies on
        assertVector(new Vector(s, s, s), octahedron.getNormal(new Point(0.2, 0.3, 0.5)), "+++ face");
        assertVector(new Vector(-s, s, -s), octahedron.getNormal(new Point(-0.2, 0.3, -0.5)), "-+- face");
        // completeHit: flat shading without vertex normals
        Ray ray = Hits.ray(0.2, 0.3, 5, 0, 0, -1);
        HitRecord hit = new HitRecord();
        assertTrue(octahedron.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        assertSame(octahedron, hit.geometry);
        octahedron.completeHit(ray, hit);
        assertEquals(0, hit.point().distance(new Point(0.2, 0.3, 0.5)), 1e-15);
        assertVector(new Vector(s, s, s), hit.normal(), "geometric");
        assertVector(new Vector(s, s, s), hit.shadingNormal(), "shading = geometric");
    }

    @Test
    void vertexNormalsAreInterpolated() {
        // one triangle with vertex normals; the geometric normal (0,0,1) is flipped if they point the other way
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        double[] n = {0, 0, 1, 1, 0, 1, 0, 1, 1};
        Mesh smooth = new Mesh(v, new int[] {0, 1, 2}, n);
        Ray ray = Hits.ray(0.25, 0.5, 1, 0, 0, -1);
        HitRecord hit = new HitRecord();
        assertTrue(smooth.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        smooth.completeHit(ray, hit);
        // barycentrics (0.25, 0.25, 0.5): 0.25 (0,0,1) + 0.25 (1,0,1) + 0.5 (0,1,1) = (0.25, 0.5, 1)
        assertVector(new Vector(0.25, 0.5, 1).normalize(), hit.shadingNormal(), "interpolated");
        assertVector(Vector.AXIS_Z, hit.normal(), "geometric");
        // flipped vertex normals flip the geometric normal too
        Mesh flipped = new Mesh(v, new int[] {0, 1, 2}, new double[] {0, 0, -1, 0, 0, -1, 0, 0, -1});
        assertTrue(flipped.intersect(ray, 0, Double.POSITIVE_INFINITY, hit.reset()));
        flipped.completeHit(ray, hit);
        assertVector(new Vector(0, 0, -1), hit.normal(), "flipped geometric");
    }

    @Test
    void rayThroughAVertexOfTheOctahedronCrossesTwice() {
        // along the x axis: in at (1,0,0), out at (-1,0,0), both vertices where four faces meet
        Ray ray = Hits.ray(3, 0, 0, -1, 0, 0);
        Hits.assertPoints(octahedron.findIntersections(ray), 1e-15, "x axis", new Point(1, 0, 0), new Point(-1, 0, 0));
        assertEquals(2, trianglesHit(OCTAHEDRON_VERTICES, OCTAHEDRON_FACES, ray));
        // through an edge midpoint and the centre
        Ray edge = Hits.ray(1, 1, 0, -1, -1, 0);
        Hits.assertPoints(
                octahedron.findIntersections(edge), 1e-15, "edge", new Point(0.5, 0.5, 0), new Point(-0.5, -0.5, 0));
        assertEquals(2, trianglesHit(OCTAHEDRON_VERTICES, OCTAHEDRON_FACES, edge));
    }

    /** Number of triangles of the mesh hit by {@code ray}, each tested alone (with the mesh's shared-edge rule). */
    static int trianglesHit(double[] vertices, int[] faces, Ray ray) {
        int count = 0;
        for (int f = 0; f < faces.length; f += 3) {
            Mesh single = new Mesh(vertices, new int[] {faces[f], faces[f + 1], faces[f + 2]});
            if (single.intersect(ray, 0, Double.POSITIVE_INFINITY, new HitRecord())) count++;
        }
        return count;
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 20).mapToObj(i -> Arguments.of(0x3E5L + 1009L * i));
    }

    /**
     * Watertightness: rays aimed exactly at vertices and at points of edges of a closed mesh, from random
     * directions into the solid, cross exactly two triangles (never slip through, never double count), also when
     * the mesh is compiled into an {@link Accelerator} with or without BVH (checked through a transparent mesh:
     * transmittance kT^2 exactly).
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void closedMeshIsWatertightAtVerticesAndEdges(long seed) {
        Random random = new Random(seed);
        // the octahedron, rotated and moved so that nothing is axis aligned
        double[] v = transformed(OCTAHEDRON_VERTICES, random);
        Mesh mesh = new Mesh(v, OCTAHEDRON_FACES);
        mesh.setMaterial(new Material().setKt(0.5));
        Accelerator bvh = Accelerator.build(new Geometries(mesh), true);
        Accelerator brute = Accelerator.build(new Geometries(mesh), false);
        Point centre = centroid(v);
        double size = centre.distance(new Point(v[0], v[1], v[2]));
        for (int i = 0; i < 200; i++) {
            Point target;
            String what;
            if (random.nextBoolean()) {
                int k = random.nextInt(6);
                target = new Point(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
                what = "vertex " + k;
            } else {
                int f = 3 * random.nextInt(8), e = random.nextInt(3);
                int a = 3 * OCTAHEDRON_FACES[f + e], b = 3 * OCTAHEDRON_FACES[f + (e + 1) % 3];
                double s = random.nextDouble();
                target = new Point(
                        v[a] + s * (v[b] - v[a]),
                        v[a + 1] + s * (v[b + 1] - v[a + 1]),
                        v[a + 2] + s * (v[b + 2] - v[a + 2]));
                what = "edge at " + s;
            }
            // toward a random point well inside, so the ray enters the solid at the target
            Point inner = centre.add(
                    SurfaceStartProperty.randomUnit(random).scale(size * (0.3 * random.nextDouble() + 1e-3)));
            Vector d = inner.subtract(target).normalize();
            Ray ray = new Ray(target.add(d.scale(-4 * size)), d);
            String where = "seed " + seed + " ray " + i + " through " + what + " " + target;
            assertEquals(2, trianglesHit(v, OCTAHEDRON_FACES, ray), where);
            assertEquals(2, mesh.findIntersections(ray).size(), where);
            Double3 viaBvh = bvh.transmittance(ray, 0, 10 * size, new HitRecord());
            Double3 viaBrute = brute.transmittance(ray, 0, 10 * size, new HitRecord());
            assertEquals(new Double3(0.25), viaBrute, where + " (brute force)");
            assertEquals(new Double3(0.25), viaBvh, where + " (BVH)");
        }
    }

    /** Random rays through a closed mesh cross it an even number of times: 0 or 2 for a convex one. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void randomRaysCrossAClosedConvexMeshZeroOrTwoTimes(long seed) {
        Random random = new Random(seed);
        double[] v = transformed(OCTAHEDRON_VERTICES, random);
        Point centre = centroid(v);
        double size = centre.distance(new Point(v[0], v[1], v[2]));
        for (int i = 0; i < 300; i++) {
            Vector d = SurfaceStartProperty.randomUnit(random);
            Point aim = centre.add(
                    SurfaceStartProperty.randomUnit(random).scale(size * (1.2 * random.nextDouble() + 1e-3)));
            Ray ray = new Ray(aim.add(d.scale(-5 * size)), d);
            int count = trianglesHit(v, OCTAHEDRON_FACES, ray);
            assertTrue(count == 0 || count == 2, "seed " + seed + " ray " + i + ": " + count + " crossings");
        }
    }

    /** The vertices rotated by a random rotation, scaled by up to 100 and moved by up to 1000. */
    static double[] transformed(double[] vertices, Random random) {
        Vector a = SurfaceStartProperty.randomUnit(random);
        Vector b = a.perpendicular();
        Vector c = a.crossProduct(b);
        double scale = Math.pow(10, random.nextDouble() * 3 - 1);
        double tx = (random.nextDouble() - 0.5) * 2000, ty = (random.nextDouble() - 0.5) * 2000;
        double tz = (random.nextDouble() - 0.5) * 2000;
        double[] out = new double[vertices.length];
        for (int i = 0; i < vertices.length; i += 3) {
            double x = vertices[i], y = vertices[i + 1], z = vertices[i + 2];
            out[i] = tx + scale * (x * a.x + y * b.x + z * c.x);
            out[i + 1] = ty + scale * (x * a.y + y * b.y + z * c.y);
            out[i + 2] = tz + scale * (x * a.z + y * b.z + z * c.z);
        }
        return out;
    }

    static Point centroid(double[] v) {
        double x = 0, y = 0, z = 0;
        int n = v.length / 3;
        for (int i = 0; i < v.length; i += 3) {
            x += v[i];
            y += v[i + 1];
            z += v[i + 2];
        }
        return new Point(x / n, y / n, z / n);
    }

    @Test
    void twoTriangleMeshSharedEdgeIsHitOnceAndItsEndsNeverTwice() {
        // the unit square split along (1,0,0) - (0,1,0)
        double[] v = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        int[] f = {0, 1, 3, 1, 2, 3};
        Vector[] directions = {
            new Vector(0, 0, -1),
            new Vector(0, 0, 1),
            new Vector(1, 1, 1),
            new Vector(-1, -2, -2),
            new Vector(0.3, -0.7, 1.1),
            new Vector(-0.0, 0.0, 1)
        };
        for (Vector d : directions) {
            for (double s : new double[] {0.5, 0.25, 0.9}) {
                Point onEdge = new Point(1 - s, s, 0);
                Ray ray = new Ray(onEdge.add(d.normalize().scale(-3)), d);
                assertEquals(1, trianglesHit(v, f, ray), "shared edge at " + onEdge + " along " + d);
            }
            // the ends of the shared edge lie on the mesh's open outline: hit by at most one triangle, never two
            for (Point end : new Point[] {new Point(1, 0, 0), new Point(0, 1, 0)}) {
                Ray ray = TriangleTest.through(end, d);
                assertTrue(trianglesHit(v, f, ray) <= 1, "end " + end + " along " + d);
            }
        }
    }

    @Test
    void openMeshFanAroundAnInteriorVertexIsHitOnce() {
        // six triangles around (0,0,0) in the plane z = 0: a ray through the centre hits exactly one of them
        double[] v = new double[3 * 7];
        int[] f = new int[3 * 6];
        for (int i = 0; i < 6; i++) {
            v[3 * (i + 1)] = Math.cos(i * Math.PI / 3);
            v[3 * (i + 1) + 1] = Math.sin(i * Math.PI / 3);
            f[3 * i + 1] = i + 1;
            f[3 * i + 2] = (i + 1) % 6 + 1;
        }
        for (Vector d : new Vector[] {
            new Vector(0, 0, 1),
            new Vector(0, 0, -1),
            new Vector(1, 1, 1),
            new Vector(-1, 2, -2),
            new Vector(0.3, -0.7, 1.1),
            new Vector(-0.0, 0.0, -1)
        }) {
            Ray ray = new Ray(Point.ZERO.add(d.normalize().scale(-3)), d);
            assertEquals(1, trianglesHit(v, f, ray), "through the centre along " + d);
            // and through the spokes
            for (int i = 1; i <= 6; i++) {
                Point spoke = new Point(0.5 * v[3 * i], 0.5 * v[3 * i + 1], 0);
                Ray r = new Ray(spoke.add(d.normalize().scale(-3)), d);
                assertEquals(1, trianglesHit(v, f, r), "through spoke " + i + " along " + d);
            }
        }
        List<Point> points = new Mesh(v, f).findIntersections(Hits.ray(0, 0, 1, 0, 0, -1));
        Hits.assertPoints(points, 0, "centre", Point.ZERO);
    }
}
