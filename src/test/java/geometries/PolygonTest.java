package geometries;

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
 * Unit tests for {@link Polygon}: validation (the course constructor cases and more), Newell's normal, and
 * intersections. A lone polygon excludes its outline; the inner diagonals of its triangle fan are shared edges,
 * hit by exactly one fan triangle.
 */
class PolygonTest {
    private static final double S = 1 / Math.sqrt(3);
    /** The course quadrangle in the plane x + y + z = 1. */
    private final Polygon quad =
            new Polygon(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0), new Point(-1, 1, 1));
    /** The unit square in z = 0 (fan diagonal from (0,0,0) to (1,1,0)). */
    private final Polygon square =
            new Polygon(new Point(0, 0, 0), new Point(1, 0, 0), new Point(1, 1, 0), new Point(0, 1, 0));

    /** Directions whose watertight shear is exact (see TriangleTest) and one that is not. */
    private static final Vector[] EXACT_DIRECTIONS = {
        new Vector(0, 0, 1), new Vector(0, 0, -1), new Vector(1, 1, 1), new Vector(-1, -2, -2), new Vector(2, 1, 2)
    };

    private static final Vector[] DIRECTIONS = {
        new Vector(0, 0, 1),
        new Vector(0, 0, -1),
        new Vector(1, 1, 1),
        new Vector(-1, -2, -2),
        new Vector(0.3, -0.7, 1.1)
    };

    private static Ray through(Point target, Vector d) {
        return TriangleTest.through(target, d);
    }

    // ============ constructor: the course cases ==============

    @Test
    void correctConcaveQuadrangleIsAccepted() {
        assertEquals(4, quad.getVertices().size());
        assertVector(new Vector(S, S, S), quad.getNormal(new Point(0, 0, 1)), "normal");
    }

    @Test
    void wrongVertexOrderIsRejected() {
        assertRejected(
                () -> new Polygon(new Point(0, 0, 1), new Point(0, 1, 0), new Point(1, 0, 0), new Point(-1, 1, 1)),
                "polygon");
    }

    @Test
    void vertexNotInThePlaneIsRejected() {
        assertRejected(
                () -> new Polygon(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0), new Point(0, 2, 2)),
                "not planar");
    }

    @Test
    void concaveQuadrangleIsRejected() {
        assertRejected(
                () -> new Polygon(
                        new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0), new Point(0.5, 0.25, 0.25)),
                "not convex");
        // an arrow head (concave at (1, 0.5))
        assertRejected(
                () -> new Polygon(
                        new Point(0, 0, 0),
                        new Point(2, 0, 0),
                        new Point(1, 0.5, 0),
                        new Point(2, 1, 0),
                        new Point(0, 1, 0)),
                "not convex");
    }

    @Test
    void lastPointEqualToTheFirstIsRejected() {
        assertRejected(
                () -> new Polygon(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0), new Point(0, 0, 1)),
                "coincide");
    }

    @Test
    void vertexOnASideIsRejected() {
        // (0, 0.5, 0.5) lies on the side from (0,1,0) back to (0,0,1)
        assertRejected(
                () -> new Polygon(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0), new Point(0, 0.5, 0.5)),
                "vertex 3");
        // a square with an extra vertex in the middle of a side, in every position
        Point[] v = {
            new Point(0, 0, 0), new Point(0.5, 0, 0), new Point(1, 0, 0), new Point(1, 1, 0), new Point(0, 1, 0)
        };
        for (int shift = 0; shift < v.length; shift++) {
            Point[] rotated = new Point[v.length];
            for (int i = 0; i < v.length; i++) rotated[i] = v[(i + shift) % v.length];
            assertRejected(() -> new Polygon(rotated), "polygon");
        }
    }

    @Test
    void selfTouchingAndSelfIntersectingPolygonsAreRejected() {
        // doubles back along its own side
        assertRejected(
                () -> new Polygon(new Point(0, 0, 0), new Point(2, 0, 0), new Point(1, 0, 0), new Point(1, 1, 0)),
                "polygon");
        // repeated consecutive vertex
        assertRejected(
                () -> new Polygon(new Point(0, 0, 0), new Point(1, 0, 0), new Point(1, 0, 0), new Point(0, 1, 0)),
                "coincide");
        // a pentagram: every turn is the same way but the outline winds twice
        Point[] star = new Point[5];
        for (int i = 0; i < 5; i++) {
            double a = Math.PI / 2 + i * 4 * Math.PI / 5;
            star[i] = new Point(Math.cos(a), Math.sin(a), 0);
        }
        assertRejected(() -> new Polygon(star), "intersects itself");
        // a bow tie (crossing sides)
        assertRejected(
                () -> new Polygon(new Point(0, 0, 0), new Point(2, 2, 0), new Point(2, 0, 0), new Point(0, 1, 0)),
                "polygon");
    }

    @Test
    void tooFewOrNullVerticesAreRejected() {
        assertRejected(() -> new Polygon(new Point(0, 0, 0), new Point(1, 0, 0)), "at least 3", "2");
        assertRejected(() -> new Polygon(), "at least 3");
        assertRejected(() -> new Polygon((Point[]) null), "at least 3");
        assertRejected(() -> new Polygon(new Point(0, 0, 0), null, new Point(0, 1, 0)), "vertex 1");
        // three collinear points
        assertRejected(() -> new Polygon(new Point(0, 0, 0), new Point(1, 0, 0), new Point(2, 0, 0)), "degenerate");
    }

    @Test
    void newellNormalIsTheOrientedUnitNormal() {
        // a regular hexagon in a tilted plane, clockwise seen from +n, so the normal is -n
        Vector n = new Vector(1, 2, 2).normalize();
        Vector u = n.perpendicular(), w = n.crossProduct(u);
        Point[] hexagon = new Point[6];
        for (int i = 0; i < 6; i++) {
            double a = -i * Math.PI / 3;
            double ca = Math.cos(a), sa = Math.sin(a);
            hexagon[i] = new Point(5 + ca * u.x + sa * w.x, -3 + ca * u.y + sa * w.y, 2 + ca * u.z + sa * w.z);
        }
        Polygon p = new Polygon(hexagon);
        assertVector(n.scale(-1), p.getNormal(hexagon[0]), "hexagon normal");
        // the polygon is not modified by later changes to the caller's array
        Point first = hexagon[0];
        hexagon[0] = Point.ZERO;
        assertEquals(first, p.getVertices().get(0));
    }

    // ============ intersections ==============

    @Test
    void insideEveryFanTriangleIsAHit() {
        // one point in each of the two fan triangles of the course quadrangle
        for (Point inside : new Point[] {new Point(0.25, 0.25, 0.5), new Point(-0.25, 0.5, 0.75)}) {
            for (Vector d : DIRECTIONS) {
                Hits.assertPoints(quad.findIntersections(through(inside, d)), 1e-14, "inside " + inside, inside);
            }
        }
    }

    @Test
    void outsideAgainstEdgeAndVertexIsAMiss() {
        for (Point outside : new Point[] {
            new Point(1, 1, -1),
            new Point(-1, 2, 0),
            new Point(2, -0.5, -0.5),
            new Point(-2, 1, 2),
            new Point(0.5, -1, 1.5)
        }) {
            for (Vector d : DIRECTIONS) assertMiss(quad, through(outside, d), "outside " + outside + " along " + d);
        }
    }

    @Test
    void outlineEdgesVerticesAndContinuationsAreMisses() {
        for (Point boundary : new Point[] {
            // on edges
            new Point(0.5, 0, 0), new Point(1, 0.5, 0), new Point(0.5, 1, 0), new Point(0, 0.5, 0),
            // vertices, including v0 where the fan's diagonals start
            new Point(0, 0, 0), new Point(1, 0, 0), new Point(1, 1, 0), new Point(0, 1, 0),
            // continuations of edges
            new Point(2, 0, 0), new Point(-1, 0, 0), new Point(1, 3, 0), new Point(0, -2, 0)
        }) {
            for (Vector d : EXACT_DIRECTIONS)
                assertMiss(square, through(boundary, d), "boundary " + boundary + " along " + d);
        }
    }

    @Test
    void innerDiagonalOfTheFanIsHitExactlyOnce() {
        for (double s : new double[] {0.5, 0.25, 0.75, 0.1, 0.9}) {
            Point onDiagonal = new Point(s, s, 0);
            for (Vector d : DIRECTIONS) {
                Ray ray = through(onDiagonal, d);
                Hits.assertPoints(square.findIntersections(ray), 1e-14, "diagonal " + s + " along " + d, onDiagonal);
                assertEquals(1, fanTrianglesHit(square, ray), "diagonal " + s + " along " + d);
            }
        }
    }

    /** How many fan triangles of {@code p} report a hit, each tested on its own with the polygon's edge flags. */
    static int fanTrianglesHit(Polygon p, Ray ray) {
        int count = 0;
        for (int i = 0; i < p.fanCount(); i++) {
            int o = 9 * i;
            if (WatertightTriangle.intersect(
                    p.fan, o, o + 3, o + 6, p.fanSharedEdges[i], ray, 0, Double.POSITIVE_INFINITY, new HitRecord())) {
                count++;
            }
        }
        return count;
    }

    @Test
    void parallelAndStartingOnThePolygon() {
        assertMiss(square, Hits.ray(-1, 0.5, 1, 1, 0, 0), "parallel");
        assertMiss(square, Hits.ray(-1, 0.5, 0, 1, 0, -0.0), "in the plane, -0.0");
        assertMiss(square, Hits.ray(0.3, 0.6, 0, 0, 0, 1), "starting on it");
        assertMiss(square, Hits.ray(0.3, 0.6, 0, 1, 1, -1), "starting on it, oblique");
    }

    @Test
    void boundingBoxAndCompleteHit() {
        assertEquals(new BoundingBox(-1, 0, 0, 1, 1, 1), quad.getBoundingBox());
        Ray ray = Hits.ray(-0.25, 0.5, 2, 0, 0, -1);
        HitRecord hit = new HitRecord();
        assertTrue(quad.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        quad.completeHit(ray, hit);
        assertEquals(1, hit.part, "the second fan triangle");
        assertEquals(0, hit.point().distance(new Point(-0.25, 0.5, 0.75)), 1e-15);
        assertVector(new Vector(S, S, S), hit.normal(), "normal");
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 20).mapToObj(i -> Arguments.of(0x9017L + 3L * i));
    }

    /**
     * Random convex polygons (points on an ellipse in a random plane) and random rays: a ray hits iff its target
     * is inside the polygon by a margin, and a ray through a random point of a fan diagonal hits exactly one fan
     * triangle.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void randomConvexPolygons(long seed) {
        Random random = new Random(seed);
        for (int k = 0; k < 20; k++) {
            Vector n = SurfaceStartProperty.randomUnit(random);
            Vector u = n.perpendicular(), w = n.crossProduct(u);
            Point c = new Point(random.nextGaussian() * 10, random.nextGaussian() * 10, random.nextGaussian() * 10);
            double ra = 0.5 + 3 * random.nextDouble(), rb = 0.5 + 3 * random.nextDouble();
            int count = 3 + random.nextInt(8);
            double[] angles = random.doubles(count, 0, 2 * Math.PI).sorted().toArray();
            Point[] v = new Point[count];
            double[][] uv = new double[count][];
            for (int i = 0; i < count; i++) {
                uv[i] = new double[] {ra * Math.cos(angles[i]), rb * Math.sin(angles[i])};
                v[i] = c.add(u.scale(uv[i][0])).add(w.scale(uv[i][1]));
            }
            Polygon p;
            try {
                p = new Polygon(v);
            } catch (IllegalArgumentException nearlyDegenerate) {
                continue;
            }
            for (int i = 0; i < 30; i++) {
                double x = (random.nextDouble() * 2 - 1) * 4, y = (random.nextDouble() * 2 - 1) * 4;
                double margin = signedDistanceInside(uv, x, y);
                if (Math.abs(margin) < 1e-6) continue;
                Point target = c.add(u.scale(x)).add(w.scale(y));
                Vector d = SurfaceStartProperty.randomUnit(random);
                if (Math.abs(d.dotProduct(n)) < 1e-2) continue;
                List<Point> points = p.findIntersections(new Ray(target.add(d.scale(-3)), d));
                String where = "seed " + seed + " polygon " + k + " target (" + x + ", " + y + ") margin " + margin;
                if (margin > 0) {
                    Hits.assertPoints(points, 1e-9, where, target);
                } else {
                    assertEquals(0, points.size(), where + " -> " + points);
                }
            }
            // points on the fan diagonals v0 - v[j], 2 <= j <= count - 2
            for (int j = 2; j <= count - 2; j++) {
                double s = 0.05 + 0.9 * random.nextDouble();
                Point target = new Point(
                        v[0].x + s * (v[j].x - v[0].x), v[0].y + s * (v[j].y - v[0].y), v[0].z + s * (v[j].z - v[0].z));
                Vector d = SurfaceStartProperty.randomUnit(random);
                if (Math.abs(d.dotProduct(n)) < 1e-2) continue;
                assertEquals(
                        1,
                        fanTrianglesHit(p, new Ray(target.add(d.scale(-3)), d)),
                        "seed " + seed + " polygon " + k + " diagonal to " + j + " at " + s);
            }
        }
    }

    /** Distance inside the convex polygon with counter-clockwise 2D vertices (negative outside). */
    private static double signedDistanceInside(double[][] uv, double x, double y) {
        double min = Double.POSITIVE_INFINITY;
        for (int i = 0; i < uv.length; i++) {
            double[] a = uv[i], b = uv[(i + 1) % uv.length];
            double ex = b[0] - a[0], ey = b[1] - a[1];
            double len = Math.hypot(ex, ey);
            min = Math.min(min, (ex * (y - a[1]) - ey * (x - a[0])) / len);
        }
        return min;
    }
}
