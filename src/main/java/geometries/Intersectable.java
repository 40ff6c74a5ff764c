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
     *
     * @param ray the ray
     * @param tMin the start of the searched interval, exclusive
     * @param tMax the end of the searched interval, exclusive; may be infinite
     * @param hit the record receiving the closest hit
     * @return true when a hit was found in the interval
     */
    boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit);

    /**
     * Whether anything lies on the ray with {@code tMin < t < tMax} (an any-hit query: it may stop at the first
     * occluder found). {@code scratch} may be overwritten.
     *
     * @param ray the ray
     * @param tMin the start of the searched interval, exclusive
     * @param tMax the end of the searched interval, exclusive; may be infinite
     * @param scratch a record the query may overwrite
     * @return true when something lies on the ray in the interval
     */
    default boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        return intersect(ray, tMin, tMax, scratch);
    }

    /**
     * Marks the segments of {@code packet} this object blocks: for each segment not blocked yet, the answer of
     * {@link #occludes} over the segment's interval, {@code (0, tMax)}. Overridden where a loop over the segments
     * gives the same answers faster (with {@link ShadowPacket#segment}, {@link ShadowPacket#end} and
     * {@link ShadowPacket#block}).
     *
     * @param packet the segments; those found blocked are marked
     * @param scratch a record the queries may overwrite
     */
    default void blockAll(ShadowPacket packet, HitRecord scratch) {
        packet.blockEach(this, scratch);
    }

    /**
     * The axis-aligned bounds, or {@code null} for unbounded geometry (planes, infinite tubes).
     *
     * @return the bounding box, or null when unbounded
     */
    BoundingBox getBoundingBox();

    /**
     * All intersection points with {@code t > 0}, nearest first; empty when the ray misses. A convenience for
     * tests and users: it allocates, and the renderer does not use it.
     *
     * @param ray the ray
     * @return a new list of the intersection points, nearest first
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
