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
        double t = hitDistance(ray.ox(), ray.oy(), ray.oz(), ray.dx(), ray.dy(), ray.dz(), tMin, tMax);
        if (!(t > tMin)) return false; // NaN: no hit in the interval
        hit.t = t;
        hit.geometry = this;
        hit.part = 0;
        hit.u = hit.v = 0; // no surface parametrisation: never leave another primitive's values behind
        return true;
    }

    /**
     * The nearest root of the ray (origin o, unit direction d) in {@code (tMin, tMax)}, or NaN when there is none: the
     * one computation behind {@link #intersect} and {@link #blockAll}, so that both give the same answers.
     */
    private double hitDistance(
            double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        double fx = ox - center.x, fy = oy - center.y, fz = oz - center.z;
        double b = -(fx * dx + fy * dy + fz * dz);
        double lx = fx + b * dx, ly = fy + b * dy, lz = fz + b * dz;
        double discriminant = radiusSquared - (lx * lx + ly * ly + lz * lz);
        if (!(discriminant > 0)) return Double.NaN;
        double q = b + Math.copySign(Math.sqrt(discriminant), b);
        if (q == 0) return Double.NaN;
        double c = fx * fx + fy * fy + fz * fz - radiusSquared;
        double t0 = c / q;
        double t1 = q;
        if (t0 > t1) {
            double s = t0;
            t0 = t1;
            t1 = s;
        }
        if (t0 > tMin && t0 < tMax) return t0;
        if (t1 > tMin && t1 < tMax) return t1;
        return Double.NaN;
    }

    /**
     * The packet's open segments against this sphere in one loop, by the arithmetic of {@link #intersect} (a subclass,
     * which may intersect otherwise, tests them one by one through its own queries).
     */
    @Override
    public void blockAll(ShadowPacket packet, HitRecord scratch) {
        if (getClass() != Sphere.class) {
            packet.blockEach(this, scratch);
            return;
        }
        boolean[] blocked = packet.blocked;
        double[] ox = packet.ox, oy = packet.oy, oz = packet.oz, dx = packet.dx, dy = packet.dy, dz = packet.dz;
        double[] tMax = packet.tMax;
        for (int i = 0, n = packet.size; i < n; i++) {
            if (!blocked[i] && hitDistance(ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], 0, tMax[i]) > 0) packet.block(i);
        }
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
