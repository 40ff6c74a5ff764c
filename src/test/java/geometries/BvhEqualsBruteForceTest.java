package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The BVH must be invisible: for seeded random scenes holding every kind of geometry and seeded random rays
 * (including rays aimed exactly at shared vertices and edges, axis-parallel rays and rays hitting duplicated
 * primitives at equal distance), a BVH-backed {@link Accelerator} answers every query exactly as the brute-force
 * scan over the same primitives: the same geometry and part, the same distance and surface coordinates bit for
 * bit, the same any-hit answer and the same transmittance.
 */
class BvhEqualsBruteForceTest {
    private static final int RAYS_PER_SCENE = 400;

    static LongStream seeds() {
        return LongStream.rangeClosed(1, 12);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void bvhAnswersEveryQueryLikeBruteForce(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        RandomScene scene = RandomScene.create(random);
        // Odd build settings as well as the defaults: tiny leaves, few bins, big leaves.
        int[][] settings = {{Accelerator.DEFAULT_BINS, Accelerator.DEFAULT_MAX_LEAF_SIZE}, {2, 1}, {32, 16}};
        int[] chosen = settings[(int) (seed % settings.length)];
        Accelerator bvh = Accelerator.build(scene.root, true, chosen[0], chosen[1]);
        Accelerator brute = Accelerator.build(scene.root, false);
        assertEquals(brute.boundedPrimitiveCount(), bvh.boundedPrimitiveCount(), "seed " + seed);

        HitRecord a = new HitRecord(), b = new HitRecord();
        for (int i = 0; i < RAYS_PER_SCENE; i++) {
            Ray ray = scene.randomRay(random);
            double tMin = random.nextInt(4) == 0 ? random.nextDouble() : 0;
            double tMax = random.nextInt(3) == 0 ? tMin + 10 * random.nextDouble() : Double.POSITIVE_INFINITY;
            String where = "seed " + seed + ", ray " + i + " " + ray + ", interval (" + tMin + ", " + tMax + ")";

            boolean hitA = bvh.intersect(ray, tMin, tMax, a.reset());
            boolean hitB = brute.intersect(ray, tMin, tMax, b.reset());
            assertEquals(hitB, hitA, "closest hit found, " + where);
            if (hitA) {
                assertEquals(Double.doubleToLongBits(b.t), Double.doubleToLongBits(a.t), "t, " + where);
                assertSame(b.geometry, a.geometry, "geometry, " + where);
                assertEquals(b.part, a.part, "part, " + where);
                assertEquals(Double.doubleToLongBits(b.u), Double.doubleToLongBits(a.u), "u, " + where);
                assertEquals(Double.doubleToLongBits(b.v), Double.doubleToLongBits(a.v), "v, " + where);
                assertEquals(b.primitiveIndex, a.primitiveIndex, "primitive index, " + where);
            }
            assertEquals(brute.occludes(ray, tMin, tMax, b), bvh.occludes(ray, tMin, tMax, a), "occludes, " + where);
            Double3 ta = bvh.transmittance(ray, tMin, tMax, a);
            Double3 tb = brute.transmittance(ray, tMin, tMax, b);
            assertEquals(bits(tb), bits(ta), "transmittance " + tb + " vs " + ta + ", " + where);
            // The occluder cache changes the work, never the answer: any hint, valid or not, gives the same.
            a.occluderHint = random.nextInt(bvh.boundedPrimitiveCount() + 2) - 1;
            b.occluderHint = a.occluderHint;
            Double3 hintedA = bvh.transmittance(ray, tMin, tMax, a);
            Double3 hintedB = brute.transmittance(ray, tMin, tMax, b);
            a.occluderHint = b.occluderHint = -1;
            assertEquals(bits(ta), bits(hintedA), "transmittance with hint, " + where);
            assertEquals(bits(tb), bits(hintedB), "brute-force transmittance with hint, " + where);
        }
    }

    private static List<Long> bits(Double3 d) {
        return List.of(Double.doubleToLongBits(d.d1), Double.doubleToLongBits(d.d2), Double.doubleToLongBits(d.d3));
    }

    /** A random scene of every geometry type, with the vertices rays may be aimed at. */
    static final class RandomScene {
        final Geometries root = new Geometries();
        /** Interesting target points: triangle vertices, edge midpoints, sphere centres. */
        final List<Point> targets = new ArrayList<>();

        static RandomScene create(SplittableRandom random) {
            RandomScene s = new RandomScene();
            Material glass = new Material().setKt(0.6);
            Material tinted = new Material().setKt(new Double3(0.9, 0.5, 0.25));
            for (int i = 0, n = 4 + random.nextInt(12); i < n; i++) {
                Point c = s.randomPoint(random, 5);
                Sphere sphere = new Sphere(c, 0.05 + random.nextDouble());
                s.root.add(sphere);
                s.targets.add(c);
                if (random.nextInt(4) == 0) sphere.setMaterial(glass);
                // An exact duplicate: equal distances must resolve to the first added in both modes.
                if (random.nextInt(5) == 0) s.root.add(new Sphere(c, sphere.getRadius()));
            }
            for (int i = 0, n = 4 + random.nextInt(12); i < n; i++) {
                Point p0 = s.randomPoint(random, 5);
                Point p1 = p0.add(s.randomVector(random, 1.5));
                Point p2 = p0.add(s.randomVector(random, 1.5));
                Triangle triangle = new Triangle(p0, p1, p2);
                s.root.add(triangle);
                s.aimAtTriangle(p0, p1, p2);
                if (random.nextInt(4) == 0) triangle.setMaterial(tinted);
                if (random.nextInt(5) == 0) s.root.add(new Triangle(p0, p1, p2));
            }
            // A strip of triangles sharing edges (watertight outline marking across separate geometries).
            Point base = s.randomPoint(random, 3);
            for (int i = 0; i < 4; i++) {
                Point a = base.add(new Vector(i, 0, 0.1)), b = base.add(new Vector(i + 1, 0, 0.2));
                Point c = base.add(new Vector(i, 1, 0.3)), d = base.add(new Vector(i + 1, 1, 0.4));
                s.root.add(new Triangle(a, b, c), new Triangle(b, d, c));
                s.aimAtTriangle(a, b, c);
                s.aimAtTriangle(b, d, c);
            }
            for (int i = 0, n = 2 + random.nextInt(6); i < n; i++) {
                Point c = s.randomPoint(random, 5);
                Vector u = s.randomVector(random, 1);
                Vector v = u.crossProduct(s.randomVector(random, 1));
                Point[] quad = {c.add(u), c.add(v), c.add(u.scale(-1)), c.add(v.scale(-1))};
                Polygon polygon = new Polygon(quad);
                if (random.nextInt(3) == 0) polygon.setMaterial(glass);
                s.root.add(polygon);
                s.aimAtTriangle(quad[0], quad[1], quad[2]);
                s.aimAtTriangle(quad[0], quad[2], quad[3]);
            }
            for (int i = 0, n = 1 + random.nextInt(4); i < n; i++) {
                Point c = s.randomPoint(random, 5);
                s.root.add(new Cylinder(
                        0.1 + random.nextDouble(),
                        new Ray(c, s.randomVector(random, 1)),
                        0.2 + 2 * random.nextDouble()));
                s.targets.add(c);
            }
            // Unbounded geometry beside the tree: a tube and a plane (sometimes transparent).
            s.root.add(new Tube(0.3, new Ray(s.randomPoint(random, 5), s.randomVector(random, 1))));
            Plane plane =
                    new Plane(new Point(0, 0, -6), s.randomVector(random, 0.2).add(new Vector(0, 0, 1)));
            if (random.nextBoolean()) plane.setMaterial(glass);
            s.root.add(plane);
            // Meshes: a closed icosphere and a heightfield, scaled and moved, in a nested composite. The icosphere has
            // 1,280 triangles, enough for the leaf filter (LeafFilter.MIN_MESH) where the JVM has it; the heightfield
            // is too small, so both kinds of leaves meet the same rays.
            s.root.add(new Geometries(
                    s.transformed(Meshes.icosphere(3), random),
                    s.transformed(Meshes.heightfield(4 + random.nextInt(12)), random)));
            return s;
        }

        private Mesh transformed(Mesh mesh, SplittableRandom random) {
            double scale = 0.5 + 2 * random.nextDouble();
            Point offset = randomPoint(random, 4);
            double[] v = mesh.vertices.clone();
            for (int i = 0; i < v.length; i += 3) {
                v[i] = v[i] * scale + offset.x;
                v[i + 1] = v[i + 1] * scale + offset.y;
                v[i + 2] = v[i + 2] * scale + offset.z;
            }
            Mesh moved = new Mesh(v, mesh.indices);
            int[] idx = mesh.indices;
            for (int t = 0; t < 40; t++) {
                int f = 3 * random.nextInt(idx.length / 3);
                aimAtTriangle(moved.vertex(idx[f]), moved.vertex(idx[f + 1]), moved.vertex(idx[f + 2]));
            }
            return moved;
        }

        private void aimAtTriangle(Point p0, Point p1, Point p2) {
            targets.add(p0);
            targets.add(new Point((p0.x + p1.x) / 2, (p0.y + p1.y) / 2, (p0.z + p1.z) / 2));
            targets.add(new Point((p0.x + p1.x + p2.x) / 3, (p0.y + p1.y + p2.y) / 3, (p0.z + p1.z + p2.z) / 3));
        }

        Ray randomRay(SplittableRandom random) {
            Point origin = randomPoint(random, random.nextInt(10) == 0 ? 200 : 8);
            switch (random.nextInt(4)) {
                case 0: // at a vertex, edge midpoint, centroid or centre
                    Point target = targets.get(random.nextInt(targets.size()));
                    return target.equals(origin)
                            ? new Ray(origin, Vector.AXIS_Z)
                            : new Ray(origin, target.subtract(origin));
                case 1: // parallel to an axis: zero direction components give infinite reciprocals
                    double sign = random.nextBoolean() ? 1 : -1;
                    int axis = random.nextInt(3);
                    return new Ray(
                            origin, new Vector(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0));
                case 2: // in a coordinate plane
                    return new Ray(origin, new Vector(random.nextDouble() - 0.5, random.nextDouble() - 0.5, 0));
                default:
                    return new Ray(origin, randomVector(random, 1));
            }
        }

        Point randomPoint(SplittableRandom random, double half) {
            return new Point(
                    half * (2 * random.nextDouble() - 1),
                    half * (2 * random.nextDouble() - 1),
                    half * (2 * random.nextDouble() - 1));
        }

        Vector randomVector(SplittableRandom random, double length) {
            double z = 2 * random.nextDouble() - 1, phi = 2 * Math.PI * random.nextDouble();
            double r = Math.sqrt(1 - z * z);
            return new Vector(length * r * Math.cos(phi), length * r * Math.sin(phi), length * z);
        }
    }
}
