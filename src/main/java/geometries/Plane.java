package geometries;

import static primitives.Util.gamma;

import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * An infinite plane through a point with a unit normal. Unbounded, so the BVH tests it beside the tree.
 * A ray parallel to the plane (including a direction component of negative zero) never hits it.
 */
public class Plane extends Geometry {
    private final Point point;
    private final Vector normal;

    /**
     * The plane through {@code point} perpendicular to {@code normal} (normalized here).
     *
     * @param point a point of the plane; not null
     * @param normal the plane's normal, any length; not null
     */
    public Plane(Point point, Vector normal) {
        this.point = Util.requireNonNull(point, "plane point");
        this.normal = Util.requireNonNull(normal, "plane normal").normalize();
    }

    /**
     * The plane through three points; collinear or coincident points are an error.
     *
     * @param p1 the first point; not null
     * @param p2 the second point; not null
     * @param p3 the third point; not null
     * @throws IllegalArgumentException if a point is null, or the points coincide or are collinear
     */
    public Plane(Point p1, Point p2, Point p3) {
        Util.requireNonNull(p1, "plane point p1");
        Util.requireNonNull(p2, "plane point p2");
        Util.requireNonNull(p3, "plane point p3");
        if (p1.equals(p2) || p2.equals(p3) || p1.equals(p3)) {
            throw new IllegalArgumentException(
                    "a plane needs three distinct points, but got " + p1 + ", " + p2 + ", " + p3);
        }
        Vector n;
        try {
            n = p2.subtract(p1).crossProduct(p3.subtract(p1));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(
                    "the points " + p1 + ", " + p2 + ", " + p3 + " are collinear and do not define a plane", e);
        }
        this.point = p1;
        this.normal = n.normalize();
    }

    /**
     * The point the plane was defined by.
     *
     * @return a point of the plane
     */
    public Point getPoint() {
        return point;
    }

    /**
     * The plane's normal.
     *
     * @return the unit normal
     */
    public Vector getNormal() {
        return normal;
    }

    @Override
    public Vector getNormal(Point p) {
        return normal;
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        double denominator = normal.x * ray.dx() + normal.y * ray.dy() + normal.z * ray.dz();
        if (denominator == 0) return false;
        double numerator =
                normal.x * (point.x - ray.ox()) + normal.y * (point.y - ray.oy()) + normal.z * (point.z - ray.oz());
        double t = numerator / denominator;
        if (!(t > tMin && t < tMax)) return false;
        hit.t = t;
        hit.geometry = this;
        hit.part = 0;
        hit.u = hit.v = 0; // no surface parametrisation: never leave another primitive's values behind
        return true;
    }

    @Override
    public BoundingBox getBoundingBox() {
        return null;
    }

    @Override
    public void completeHit(Ray ray, HitRecord hit) {
        completePlanarHit(ray, hit, point, normal);
        hit.setNormal(normal);
    }

    /**
     * The hit point {@code o + t d}, projected back onto the plane through {@code q} with unit normal {@code n},
     * and its error bound: the projection removes the error of {@code t}, leaving a few ulps of the coordinates.
     */
    static void completePlanarHit(Ray ray, HitRecord hit, Point q, Vector n) {
        double t = hit.t;
        double px = ray.ox() + t * ray.dx(), py = ray.oy() + t * ray.dy(), pz = ray.oz() + t * ray.dz();
        double s = n.x * (px - q.x) + n.y * (py - q.y) + n.z * (pz - q.z);
        px -= s * n.x;
        py -= s * n.y;
        pz -= s * n.z;
        hit.setPoint(px, py, pz);
        double g = gamma(5);
        hit.setError(
                g * (Math.abs(px) + Math.abs(q.x)),
                g * (Math.abs(py) + Math.abs(q.y)),
                g * (Math.abs(pz) + Math.abs(q.z)));
    }
}
