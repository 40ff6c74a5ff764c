package robustness;

import geometries.Accelerator;
import geometries.Geometries;
import geometries.HitRecord;
import geometries.Sphere;
import java.util.SplittableRandom;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.SurfacePoint;

/**
 * Measures the opposite failure of acne: an offset so large that a ray leaving a surface starts beyond a nearby
 * one. A unit sphere sits inside a concentric sphere {@code gap} larger; every ray spawned outward from the inner
 * sphere must hit the outer one (and not the inner one again).
 */
public final class ThinGapProbe {
    /** Spawned rays that escaped through the gap or hit their own sphere. */
    public record Result(long spawned, long escaped, long selfHits) {
        /**
         * The spawned rays that failed.
         *
         * @return escapes plus self-hits
         */
        public long failures() {
            return escaped + selfHits;
        }
    }

    private ThinGapProbe() {}

    /**
     * Spawns rays outward from a unit sphere inside a concentric sphere {@code gap} larger and counts the failures.
     *
     * @param distance the distance of the spheres' centre from the origin, in scene units
     * @param gap how much larger the outer sphere's radius is
     * @param probes the number of primary rays shot at the inner sphere
     * @param seed the random seed of the rays
     * @param useBvh true to search with the BVH, false by brute force
     * @return the spawned rays, escapes and self-hits
     */
    public static Result run(double distance, double gap, int probes, long seed, boolean useBvh) {
        Point centre = AcneProbe.placement(distance);
        Sphere inner = new Sphere(centre, 1);
        Sphere outer = new Sphere(centre, 1 + gap);
        Accelerator innerOnly = Accelerator.build(new Geometries(inner), useBvh);
        Accelerator both = Accelerator.build(new Geometries(inner, outer), useBvh);
        SplittableRandom random = new SplittableRandom(seed);
        HitRecord hit = new HitRecord();
        long spawned = 0, escaped = 0, selfHits = 0;
        for (int i = 0; i < probes; i++) {
            Point eye = centre.add(AcneProbe.randomUnit(random).scale(3 + 5 * random.nextDouble()));
            Point aim = centre.add(AcneProbe.randomUnit(random).scale(0.7 * random.nextDouble()));
            Ray primary = new Ray(eye, aim.subtract(eye));
            hit.reset();
            if (!innerOnly.intersect(primary, 0, Double.POSITIVE_INFINITY, hit)) continue;
            hit.complete(primary);
            SurfacePoint sp = new SurfacePoint(hit);
            Vector out = AcneProbe.randomInHemisphere(random, sp.normal());
            spawned++;
            hit.reset();
            if (!both.intersect(sp.spawnRay(out), 0, Double.POSITIVE_INFINITY, hit)) escaped++;
            else if (hit.geometry == inner) selfHits++;
        }
        return new Result(spawned, escaped, selfHits);
    }
}
