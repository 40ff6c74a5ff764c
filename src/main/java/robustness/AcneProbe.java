package robustness;

import geometries.Accelerator;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.HitRecord;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import java.util.SplittableRandom;
import java.util.function.Function;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.SurfacePoint;

/**
 * Measures self-intersection ("shadow acne"): rays spawned from hits on a convex shape must never hit that
 * shape again. Each probe aims a ray at a random point of the shape from a random point outside it, then spawns
 * a reflection ray and a shadow ray toward a random direction of the same hemisphere, both from
 * {@link SurfacePoint#spawnOrigin}, and counts the spawned rays that hit the shape.
 */
public final class AcneProbe {
    /** A convex test shape placed around a centre point, with an oblique orientation. */
    public enum Shape {
        /** A unit sphere. */
        SPHERE(c -> new Sphere(c, 1)),
        /** An oblique triangle about 1.8 across. */
        TRIANGLE(c -> new Triangle(
                c.add(new Vector(-0.9, -0.35, 0.2)),
                c.add(new Vector(0.8, -0.5, -0.3)),
                c.add(new Vector(0.1, 0.9, 0.45)))),
        /** An oblique convex pentagon. */
        POLYGON(c -> new Polygon(
                onObliquePlane(c, -0.8, -0.6),
                onObliquePlane(c, 0.7, -0.7),
                onObliquePlane(c, 0.9, 0.5),
                onObliquePlane(c, -0.1, 0.95),
                onObliquePlane(c, -0.7, 0.4))),
        /** An oblique cylinder of radius 0.6 and height 1.2. */
        CYLINDER(c -> new Cylinder(0.6, new Ray(c.add(new Vector(-0.4, -0.3, -0.5)), new Vector(0.5, 0.4, 1)), 1.2));

        private final Function<Point, Geometry> factory;

        Shape(Function<Point, Geometry> factory) {
            this.factory = factory;
        }

        /**
         * The shape around {@code centre}.
         *
         * @param centre the point the shape is placed around
         * @return a new geometry of this shape
         */
        public Geometry at(Point centre) {
            return factory.apply(centre);
        }
    }

    private static final Vector U = new Vector(0.8, 0.36, -0.48);
    private static final Vector V = new Vector(-0.28, 0.9, 0.33);

    /** The point {@code c + a U + b V} of an oblique plane through {@code c}. */
    private static Point onObliquePlane(Point c, double a, double b) {
        return new Point(c.x + a * U.x + b * V.x, c.y + a * U.y + b * V.y, c.z + a * U.z + b * V.z);
    }

    /** Self-hits among the spawned rays. */
    public record Result(long spawned, long selfHits, long primaryMisses, long nonFinite) {
        /**
         * The fraction of spawned rays that hit their own surface.
         *
         * @return selfHits / spawned, or 0 when no ray was spawned
         */
        public double rate() {
            return spawned == 0 ? 0 : (double) selfHits / spawned;
        }
    }

    private AcneProbe() {}

    /**
     * The centre of a shape placed {@code distance} from the origin along a fixed oblique direction.
     *
     * @param distance the distance from the origin, in scene units
     * @return the centre point
     */
    public static Point placement(double distance) {
        Vector direction = new Vector(0.48, 0.64, 0.6).normalize();
        return new Point(distance * direction.x, distance * direction.y, distance * direction.z);
    }

    /**
     * Runs {@code probes} probes on {@code shape} at {@code distance}, searching with the BVH or brute force.
     *
     * @param shape the shape probed
     * @param distance the distance of the shape from the origin, in scene units
     * @param probes the number of primary rays shot at the shape
     * @param seed the random seed of the rays
     * @param useBvh true to search with the BVH, false by brute force
     * @return the spawned rays, self-hits, missed primaries and non-finite hits
     */
    public static Result run(Shape shape, double distance, int probes, long seed, boolean useBvh) {
        Point centre = placement(distance);
        Geometry geometry = shape.at(centre);
        Accelerator scene = Accelerator.build(new Geometries(geometry), useBvh);
        SplittableRandom random = new SplittableRandom(seed);
        HitRecord hit = new HitRecord();
        long spawned = 0, selfHits = 0, misses = 0, nonFinite = 0;
        for (int i = 0; i < probes; i++) {
            Vector toEye = randomUnit(random);
            Point eye = centre.add(toEye.scale(3 + 5 * random.nextDouble()));
            Point aim = centre.add(randomUnit(random).scale(0.5 * random.nextDouble()));
            Ray primary = new Ray(eye, aim.subtract(eye));
            hit.reset();
            if (!scene.intersect(primary, 0, Double.POSITIVE_INFINITY, hit)) {
                misses++;
                continue;
            }
            hit.complete(primary);
            if (!finite(hit)) {
                nonFinite++;
                continue;
            }
            SurfacePoint sp = new SurfacePoint(hit);
            Vector d = primary.getDirection();
            Vector n = sp.normal();
            double dn = d.dotProduct(n);
            // The side the primary ray came from: spawned rays leave toward it.
            Vector outward = dn < 0 ? n : n.scale(-1);
            Vector reflected = d.subtract(n.scale(2 * dn));
            Vector towardLight = randomInHemisphere(random, outward);
            for (Vector direction : new Vector[] {reflected, towardLight}) {
                spawned++;
                hit.reset();
                if (scene.intersect(sp.spawnRay(direction), 0, Double.POSITIVE_INFINITY, hit)) selfHits++;
            }
        }
        return new Result(spawned, selfHits, misses, nonFinite);
    }

    static boolean finite(HitRecord hit) {
        return Double.isFinite(hit.t)
                && Double.isFinite(hit.errorX)
                && Double.isFinite(hit.errorY)
                && Double.isFinite(hit.errorZ)
                && Double.isFinite(hit.px + hit.py + hit.pz)
                && Double.isFinite(hit.nx + hit.ny + hit.nz);
    }

    static Vector randomUnit(SplittableRandom random) {
        while (true) {
            double x = 2 * random.nextDouble() - 1, y = 2 * random.nextDouble() - 1, z = 2 * random.nextDouble() - 1;
            double l2 = x * x + y * y + z * z;
            if (l2 > 1e-6 && l2 <= 1) return new Vector(x, y, z).normalize();
        }
    }

    /** A random unit vector with a positive component along {@code n}, grazing directions included. */
    static Vector randomInHemisphere(SplittableRandom random, Vector n) {
        while (true) {
            Vector v = randomUnit(random);
            double along = v.dotProduct(n);
            if (along > 0) return v;
            if (along < 0) return v.scale(-1);
        }
    }
}
