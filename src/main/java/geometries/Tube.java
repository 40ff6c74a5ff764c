package geometries;

import static primitives.Util.differenceOfProducts;
import static primitives.Util.gamma;

import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * An infinite circular tube around an axis ray. Unbounded, so the BVH tests it beside the tree.
 *
 * <p>The quadratic is set up with cross products with the unit axis {@code v}: a point {@code o + t d} lies on
 * the tube when {@code |(f + t d) x v| = r} with {@code f = o - p0}. Cross products computed by FMA differences
 * are exactly zero for a ray parallel to the axis (no hit) and accurate for nearly parallel ones, and the roots
 * use the same cancellation-free discriminant and stable pair as {@link Sphere}.
 */
public class Tube extends Geometry {
    /** The axis: a point on it and the unit direction. */
    protected final Ray axis;
    /** The radius. */
    protected final double radius;
    /** The radius squared. */
    protected final double radiusSquared;

    /**
     * An infinite tube of the given radius around an axis.
     *
     * @param radius the radius, positive and finite
     * @param axis the axis; not null
     * @throws IllegalArgumentException if the axis is null or the radius is not positive and finite
     */
    public Tube(double radius, Ray axis) {
        this.axis = Util.requireNonNull(axis, "tube axis");
        this.radius = Util.requirePositive(radius, "tube radius");
        this.radiusSquared = radius * radius;
    }

    /**
     * The axis.
     *
     * @return the axis ray
     */
    public Ray getAxis() {
        return axis;
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
        Point p0 = axis.getHead();
        Vector v = axis.getDirection();
        double h = (point.x - p0.x) * v.x + (point.y - p0.y) * v.y + (point.z - p0.z) * v.z;
        return point.subtract(h == 0 ? p0 : p0.add(v.scale(h))).normalize();
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        return intersectSide(ray, tMin, tMax, hit, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
    }

    /**
     * The closest hit of the lateral surface whose axial coordinate lies strictly in {@code (hMin, hMax)}; the
     * roots are tried nearest first.
     *
     * @param ray the ray
     * @param tMin the start of the searched interval, exclusive
     * @param tMax the end of the searched interval, exclusive
     * @param hit the record receiving the hit
     * @param hMin the lower bound of the axial coordinate, exclusive
     * @param hMax the upper bound of the axial coordinate, exclusive
     * @return true when a hit was found
     */
    protected final boolean intersectSide(Ray ray, double tMin, double tMax, HitRecord hit, double hMin, double hMax) {
        double vx = axis.dx(), vy = axis.dy(), vz = axis.dz();
        double fx = ray.ox() - axis.ox(), fy = ray.oy() - axis.oy(), fz = ray.oz() - axis.oz();
        // F = f x v, D = d x v: the components perpendicular to the axis, rotated by 90 degrees.
        double Fx = differenceOfProducts(fy, vz, fz, vy);
        double Fy = differenceOfProducts(fz, vx, fx, vz);
        double Fz = differenceOfProducts(fx, vy, fy, vx);
        double Dx = differenceOfProducts(ray.dy(), vz, ray.dz(), vy);
        double Dy = differenceOfProducts(ray.dz(), vx, ray.dx(), vz);
        double Dz = differenceOfProducts(ray.dx(), vy, ray.dy(), vx);
        double a = Dx * Dx + Dy * Dy + Dz * Dz;
        if (a == 0) return false; // parallel to the axis
        double b = -(Fx * Dx + Fy * Dy + Fz * Dz);
        double k = b / a;
        double lx = Fx + k * Dx, ly = Fy + k * Dy, lz = Fz + k * Dz;
        double discriminant = a * (radiusSquared - (lx * lx + ly * ly + lz * lz));
        if (!(discriminant > 0)) return false;
        double q = b + Math.copySign(Math.sqrt(discriminant), b);
        if (q == 0) return false;
        double c = Fx * Fx + Fy * Fy + Fz * Fz - radiusSquared;
        double t0 = c / q;
        double t1 = q / a;
        if (t0 > t1) {
            double s = t0;
            t0 = t1;
            t1 = s;
        }
        double fv = fx * vx + fy * vy + fz * vz;
        double dv = ray.dx() * vx + ray.dy() * vy + ray.dz() * vz;
        if (t0 > tMin && t0 < tMax) {
            double h = fv + t0 * dv;
            if (h > hMin && h < hMax) return record(hit, t0);
        }
        if (t1 > tMin && t1 < tMax) {
            double h = fv + t1 * dv;
            if (h > hMin && h < hMax) return record(hit, t1);
        }
        return false;
    }

    private boolean record(HitRecord hit, double t) {
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
        completeSideHit(ray, hit);
    }

    /**
     * Hit point re-projected radially onto the lateral surface, with its error bound and outward normal.
     *
     * @param ray the ray that hit the side
     * @param hit the record holding the distance; receives the point, error bound and normal
     */
    protected final void completeSideHit(Ray ray, HitRecord hit) {
        double t = hit.t;
        double vx = axis.dx(), vy = axis.dy(), vz = axis.dz();
        double wx = ray.ox() + t * ray.dx() - axis.ox();
        double wy = ray.oy() + t * ray.dy() - axis.oy();
        double wz = ray.oz() + t * ray.dz() - axis.oz();
        double h = wx * vx + wy * vy + wz * vz;
        double rx = wx - h * vx, ry = wy - h * vy, rz = wz - h * vz;
        double length = Math.sqrt(rx * rx + ry * ry + rz * rz);
        double nx, ny, nz;
        if (length > 0) {
            nx = rx / length;
            ny = ry / length;
            nz = rz / length;
        } else { // on the axis itself: any direction across it
            Vector across = axis.getDirection().perpendicular();
            nx = across.x;
            ny = across.y;
            nz = across.z;
        }
        double px = axis.ox() + h * vx + radius * nx;
        double py = axis.oy() + h * vy + radius * ny;
        double pz = axis.oz() + h * vz + radius * nz;
        hit.setPoint(px, py, pz);
        hit.setNormal(nx, ny, nz);
        double g = gamma(4), gr = gamma(8) * radius;
        double ah = Math.abs(h);
        hit.setError(
                g * (Math.abs(px) + Math.abs(axis.ox()) + ah) + gr,
                g * (Math.abs(py) + Math.abs(axis.oy()) + ah) + gr,
                g * (Math.abs(pz) + Math.abs(axis.oz()) + ah) + gr);
    }
}
