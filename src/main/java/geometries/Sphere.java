package geometries;

import static primitives.Util.gamma;

import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A sphere given by centre and radius.
 *
 * <p>The intersection follows Ray Tracing Gems chapter 7: the discriminant {@code r^2 - |f - (f.d)d|^2} with
 * {@code f = o - c} does not cancel for small or distant spheres, and the roots come from the stable pair
 * {@code q = b + sign(b) sqrt(disc)}, {@code t0 = c/q}, {@code t1 = q}. A tangent ray (zero discriminant) touches
 * but does not hit. Hit points are re-projected onto the sphere, which bounds their error by a few ulps of the
 * coordinates plus a few ulps of the radius.
 */
public class Sphere extends Geometry {
    private final Point center;
    private final double radius;
    private final double radiusSquared;

    /**
     * A sphere of the given centre and radius.
     *
     * @param center the centre; not null
     * @param radius the radius, positive, with a positive finite square
     * @throws IllegalArgumentException if {@code center} is null or the radius is not positive or its square not finite
     */
    public Sphere(Point center, double radius) {
        this.center = Util.requireNonNull(center, "sphere center");
        this.radius = Util.requirePositive(radius, "sphere radius");
        this.radiusSquared = radius * radius;
        if (!Double.isFinite(radiusSquared) || radiusSquared == 0) {
            throw new IllegalArgumentException(
                    "sphere radius squared must be a positive finite double, but radius was " + radius);
        }
    }

    /**
     * The course order of arguments: radius first.
     *
     * @param radius the radius, positive, with a positive finite square
     * @param center the centre; not null
     */
    public Sphere(double radius, Point center) {
        this(center, radius);
    }

    /**
     * The centre.
     *
     * @return the centre point
     */
    public Point getCenter() {
        return center;
    }

    /**
     * The radius.
     *
     * @return the radius, positive
     */
    public double getRadius() {
        return radius;
    }

    @Override
    public Vector getNormal(Point point) {
        return point.subtract(center).normalize();
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        double fx = ray.ox() - center.x, fy = ray.oy() - center.y, fz = ray.oz() - center.z;
        double b = -(fx * ray.dx() + fy * ray.dy() + fz * ray.dz());
        double lx = fx + b * ray.dx(), ly = fy + b * ray.dy(), lz = fz + b * ray.dz();
        double discriminant = radiusSquared - (lx * lx + ly * ly + lz * lz);
        if (!(discriminant > 0)) return false;
        double q = b + Math.copySign(Math.sqrt(discriminant), b);
        if (q == 0) return false;
        double c = fx * fx + fy * fy + fz * fz - radiusSquared;
        double t0 = c / q;
        double t1 = q;
        if (t0 > t1) {
            double s = t0;
            t0 = t1;
            t1 = s;
        }
        double t;
        if (t0 > tMin && t0 < tMax) t = t0;
        else if (t1 > tMin && t1 < tMax) t = t1;
        else return false;
        hit.t = t;
        hit.geometry = this;
        hit.part = 0;
        hit.u = hit.v = 0; // no surface parametrisation: never leave another primitive's values behind
        return true;
    }

    @Override
    public BoundingBox getBoundingBox() {
        double r = radius * (1 + gamma(2));
        return BoundingBox.around(center.x, center.y, center.z, r, r, r);
    }

    @Override
    public void completeHit(Ray ray, HitRecord hit) {
        double t = hit.t;
        double lx = ray.ox() + t * ray.dx() - center.x;
        double ly = ray.oy() + t * ray.dy() - center.y;
        double lz = ray.oz() + t * ray.dz() - center.z;
        double length = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double nx, ny, nz;
        if (length > 0) {
            nx = lx / length;
            ny = ly / length;
            nz = lz / length;
        } else { // only for radii near underflow
            nx = -ray.dx();
            ny = -ray.dy();
            nz = -ray.dz();
        }
        // Re-project onto the sphere: the error is then that of the final sum plus a few ulps of the radius.
        double px = center.x + radius * nx;
        double py = center.y + radius * ny;
        double pz = center.z + radius * nz;
        hit.setPoint(px, py, pz);
        hit.setNormal(nx, ny, nz);
        double g = gamma(2), gr = gamma(6) * radius;
        hit.setError(g * Math.abs(px) + gr, g * Math.abs(py) + gr, g * Math.abs(pz) + gr);
    }
}
