package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Random;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The "ray starting on a surface" property shared by the geometry tests. A surface point is taken as a ray tracer
 * gets it (intersect, then {@link Geometry#completeHit}), so it lies on the surface only to rounding. Rays fired
 * from it along random directions must find exactly the hits that exist beyond rounding distance: for a convex
 * closed shape one (the far side) when leaving inward and none when leaving outward; for a plane none.
 *
 * <p>Hits within rounding distance of the start (the surface the ray starts on, seen from a point that rounding
 * put a hair inside or outside) are not judged here: avoiding them is the job of the spawned-ray offset, tested in
 * {@code renderer.SpawnedRayTest}.
 */
final class SurfaceStartProperty {
    private SurfaceStartProperty() {}

    /**
     * Probes {@code geometry} from random points around {@code around} (spread {@code spread}); returns the number
     * of rays checked. {@code closed} says whether inward rays must find the far side.
     */
    static int check(Geometry geometry, Point around, double spread, boolean closed, long seed, int tries) {
        Random random = new Random(seed);
        int checked = 0;
        double rounding = 1e-9 * (spread + Math.abs(around.x) + Math.abs(around.y) + Math.abs(around.z));
        for (int i = 0; i < tries; i++) {
            Point target = new Point(
                    around.x + spread * random.nextGaussian(),
                    around.y + spread * random.nextGaussian(),
                    around.z + spread * random.nextGaussian());
            Vector in = randomUnit(random);
            Ray probe = new Ray(target.add(in.scale(-20 * spread)), in);
            HitRecord hit = new HitRecord();
            if (!geometry.intersect(probe, 0, Double.POSITIVE_INFINITY, hit)) continue;
            geometry.completeHit(probe, hit);
            Vector out = randomUnit(random);
            double cos = out.dotProduct(hit.normal());
            if (Math.abs(cos) < 1e-3) continue; // grazing: not this property
            Point start = hit.point();
            List<Point> beyond = geometry.findIntersections(new Ray(start, out)).stream()
                    .filter(p -> p.distance(start) > rounding)
                    .toList();
            int expected = closed && cos < 0 ? 1 : 0;
            assertEquals(
                    expected,
                    beyond.size(),
                    "seed " + seed + " try " + i + ": " + geometry.getClass().getSimpleName() + " from " + start
                            + " along " + out + (cos < 0 ? " (inward)" : " (outward)") + " found " + beyond);
            checked++;
        }
        return checked;
    }

    static Vector randomUnit(Random random) {
        return new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
    }
}
