package geometries;

import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A finite, capped cylinder: the part of a {@link Tube} between the axis head and {@code height} along the axis,
 * closed by two discs. The rim belongs to the caps (distance to the axis at most the radius), the side excludes
 * it, so a ray through the rim hits exactly once.
 */
public class Cylinder extends Tube {
    private static final int SIDE = 0;
    private static final int BOTTOM = 1;
    private static final int TOP = 2;

    private final double height;
    private final Point top;

    /**
     * A capped cylinder from the axis head to {@code height} along the axis.
     *
     * @param radius the radius, positive and finite
     * @param axis the axis ray: the base centre and the direction toward the top; not null
     * @param height the distance from the base to the top cap, positive and finite
     * @throws IllegalArgumentException if a value is null, not positive or not finite
     */
    public Cylinder(double radius, Ray axis, double height) {
        super(radius, axis);
        this.height = Util.requirePositive(height, "cylinder height");
        this.top = axis.getPoint(height);
    }

    /**
     * The distance between the two caps.
     *
     * @return the height, positive
     */
    public double getHeight() {
        return height;
    }

    @Override
    public Vector getNormal(Point point) {
        Vector v = axis.getDirection();
        Point p0 = axis.getHead();
        double h = (point.x - p0.x) * v.x + (point.y - p0.y) * v.y + (point.z - p0.z) * v.z;
        double tolerance = 1e-9 * Math.max(height, radius);
        if (Math.abs(h) <= tolerance) return v.scale(-1);
        if (Math.abs(h - height) <= tolerance) return v;
        return super.getNormal(point);
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        boolean found = intersectSide(ray, tMin, tMax, hit, 0, height);
        if (found) tMax = hit.t;
        double dv = ray.dx() * axis.dx() + ray.dy() * axis.dy() + ray.dz() * axis.dz();
        if (dv == 0) return found; // parallel to the caps
        double fv = (ray.ox() - axis.ox()) * axis.dx()
                + (ray.oy() - axis.oy()) * axis.dy()
                + (ray.oz() - axis.oz()) * axis.dz();
        if (intersectCap(ray, tMin, tMax, hit, (0 - fv) / dv, BOTTOM)) {
            found = true;
            tMax = hit.t;
        }
        return intersectCap(ray, tMin, tMax, hit, (height - fv) / dv, TOP) || found;
    }

    private boolean intersectCap(Ray ray, double tMin, double tMax, HitRecord hit, double t, int part) {
        if (!(t > tMin && t < tMax)) return false;
        Point c = part == BOTTOM ? axis.getHead() : top;
        double wx = ray.ox() + t * ray.dx() - c.x,
                wy = ray.oy() + t * ray.dy() - c.y,
                wz = ray.oz() + t * ray.dz() - c.z;
        double h = wx * axis.dx() + wy * axis.dy() + wz * axis.dz();
        double rx = wx - h * axis.dx(), ry = wy - h * axis.dy(), rz = wz - h * axis.dz();
        if (rx * rx + ry * ry + rz * rz > radiusSquared) return false;
        hit.t = t;
        hit.geometry = this;
        hit.part = part;
        hit.u = hit.v = 0; // no surface parametrisation: never leave another primitive's values behind
        return true;
    }

    @Override
    public BoundingBox getBoundingBox() {
        Point p0 = axis.getHead();
        double ex = radius * Math.sqrt(Math.max(0, 1 - axis.dx() * axis.dx()));
        double ey = radius * Math.sqrt(Math.max(0, 1 - axis.dy() * axis.dy()));
        double ez = radius * Math.sqrt(Math.max(0, 1 - axis.dz() * axis.dz()));
        BoundingBox box = BoundingBox.of(p0, top);
        double pad = 1 + 1e-12;
        return new BoundingBox(
                Math.nextDown(box.minX - ex * pad),
                Math.nextDown(box.minY - ey * pad),
                Math.nextDown(box.minZ - ez * pad),
                Math.nextUp(box.maxX + ex * pad),
                Math.nextUp(box.maxY + ey * pad),
                Math.nextUp(box.maxZ + ez * pad));
    }

    @Override
    public void completeHit(Ray ray, HitRecord hit) {
        if (hit.part == SIDE) {
            completeSideHit(ray, hit);
            return;
        }
        Vector v = axis.getDirection();
        Vector normal = hit.part == TOP ? v : v.scale(-1);
        Plane.completePlanarHit(ray, hit, hit.part == TOP ? top : axis.getHead(), normal);
        hit.setNormal(normal);
    }
}
