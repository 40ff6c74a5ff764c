package robustness;

import geometries.HitRecord;
import geometries.Sphere;
import java.util.SplittableRandom;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The textbook way to spawn rays, measured for comparison only (the renderer never uses it): start at
 * {@code o + t d} moved by a fixed {@code delta} along the normal. A large delta skips thin gaps, a small one
 * re-hits the surface far from the origin; no single constant works at every distance.
 */
public final class FixedOffsetBaseline {
    /** Self-hits among rays spawned outward from a unit sphere, and escapes through a concentric gap. */
    public record Result(long spawned, long selfHits, long escaped) {}

    private FixedOffsetBaseline() {}

    /**
     * Spawns rays outward from a unit sphere by the fixed-offset method and counts self-hits and escapes through a
     * concentric sphere {@code gap} larger.
     *
     * @param distance the distance of the spheres' centre from the origin, in scene units
     * @param delta the fixed offset along the normal, in scene units
     * @param gap how much larger the outer sphere's radius is
     * @param probes the number of primary rays shot at the inner sphere
     * @param seed the random seed of the rays
     * @return the spawned rays, self-hits and escapes
     */
    public static Result run(double distance, double delta, double gap, int probes, long seed) {
        Point c = AcneProbe.placement(distance);
        Sphere inner = new Sphere(c, 1), outer = new Sphere(c, 1 + gap);
        SplittableRandom random = new SplittableRandom(seed);
        HitRecord hit = new HitRecord();
        long spawned = 0, selfHits = 0, escaped = 0;
        for (int i = 0; i < probes; i++) {
            Point eye = c.add(AcneProbe.randomUnit(random).scale(3 + 5 * random.nextDouble()));
            Point aim = c.add(AcneProbe.randomUnit(random).scale(0.7 * random.nextDouble()));
            Ray primary = new Ray(eye, aim.subtract(eye));
            hit.reset();
            if (!inner.intersect(primary, 0, Double.POSITIVE_INFINITY, hit)) continue;
            Point p = primary.getPoint(hit.t);
            Vector n = inner.getNormal(p);
            Vector out = AcneProbe.randomInHemisphere(random, n);
            Ray spawnedRay = new Ray(p.add(n.scale(delta)), out);
            spawned++;
            hit.reset();
            if (inner.intersect(spawnedRay, 0, Double.POSITIVE_INFINITY, hit)) selfHits++;
            hit.reset();
            if (!outer.intersect(spawnedRay, 0, Double.POSITIVE_INFINITY, hit)) escaped++;
        }
        return new Result(spawned, selfHits, escaped);
    }
}
