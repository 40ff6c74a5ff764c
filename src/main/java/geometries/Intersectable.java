package geometries;

import java.util.ArrayList;
import java.util.List;
import primitives.Point;
import primitives.Ray;

/**
 * Anything a ray can hit.
 *
 * <p>The core query is the closest hit within an open interval, {@code tMin < t < tMax}: on success it
 * overwrites the hit record and returns true, so callers shrink {@code tMax} to {@code hit.t} as they go (the
 * interval API of "Ray Tracing in One Weekend", pbrt's {@code Intersect}). The renderer never calls the
 * list-returning {@link #findIntersections(Ray)}; it exists for tests and users.
 */
public interface Intersectable {

    /**
     * Finds the closest intersection with {@code tMin < t < tMax}. On success fills {@code hit.t},
     * {@code hit.geometry}, {@code hit.part}, {@code hit.u}, {@code hit.v} and returns true; on failure leaves
     * the record untouched.
     */
    boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit);

    /**
     * Whether anything lies on the ray with {@code tMin < t < tMax} (an any-hit query: it may stop at the first
     * occluder found). {@code scratch} may be overwritten.
     */
    default boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        return intersect(ray, tMin, tMax, scratch);
    }

    /** The axis-aligned bounds, or {@code null} for unbounded geometry (planes, infinite tubes). */
    BoundingBox getBoundingBox();

    /**
     * All intersection points with {@code t > 0}, nearest first; empty when the ray misses. A convenience for
     * tests and users: it allocates, and the renderer does not use it.
     */
    default List<Point> findIntersections(Ray ray) {
        List<Point> points = new ArrayList<>();
        HitRecord hit = new HitRecord();
        double tMin = 0;
        while (intersect(ray, tMin, Double.POSITIVE_INFINITY, hit)) {
            points.add(ray.getPoint(hit.t));
            tMin = hit.t;
            hit.reset();
        }
        return points;
    }
}
