package primitives;

/**
 * An immutable half-line: an origin and a unit direction.
 *
 * <p>Besides the user-facing {@link #getHead()} and {@link #getDirection()}, a ray carries the per-ray constants
 * that the intersection kernels need, computed once here instead of once per box or triangle: the raw
 * coordinates, the reciprocal direction for the slab test, and the axis permutation and shear of the watertight
 * triangle test (Woop, Benthin and Wald 2013).
 */
public final class Ray {
    private final Point head;
    private final Vector direction;

    /** Origin and unit direction, unpacked for the kernels. */
    public final double ox, oy, oz, dx, dy, dz;

    /** Reciprocal direction (may be infinite for zero components). */
    public final double invDx, invDy, invDz;

    /** Watertight triangle test: the dominant axis kz and the two others, and the shear constants. */
    public final int kx, ky, kz;

    public final double shearX, shearY, shearZ;

    /**
     * A ray from {@code head} along {@code direction}, which is normalized here. A NaN or infinite origin or a
     * zero or NaN direction cannot be expressed by {@link Point} and {@link Vector}, so they are rejected there.
     */
    public Ray(Point head, Vector direction) {
        Util.requireNonNull(head, "ray origin");
        Util.requireNonNull(direction, "ray direction");
        this.head = head;
        this.direction = direction.normalize();
        ox = head.x;
        oy = head.y;
        oz = head.z;
        dx = this.direction.x;
        dy = this.direction.y;
        dz = this.direction.z;
        invDx = 1.0 / dx;
        invDy = 1.0 / dy;
        invDz = 1.0 / dz;
        double ax = Math.abs(dx);
        double ay = Math.abs(dy);
        double az = Math.abs(dz);
        int k = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kz = k;
        kx = k == 2 ? 0 : k + 1;
        ky = kx == 2 ? 0 : kx + 1;
        double dirZ = component(kz);
        shearX = -component(kx) / dirZ;
        shearY = -component(ky) / dirZ;
        shearZ = 1.0 / dirZ;
    }

    private double component(int axis) {
        return axis == 0 ? dx : axis == 1 ? dy : dz;
    }

    public Point getHead() {
        return head;
    }

    /** The unit direction. */
    public Vector getDirection() {
        return direction;
    }

    /** The point at distance {@code t} along the ray; {@code t = 0} is the head itself. */
    public Point getPoint(double t) {
        return t == 0 ? head : new Point(ox + t * dx, oy + t * dy, oz + t * dz);
    }

    @Override
    public boolean equals(Object obj) {
        return obj instanceof Ray other && head.equals(other.head) && direction.equals(other.direction);
    }

    @Override
    public int hashCode() {
        return head.hashCode() * 31 + direction.hashCode();
    }

    @Override
    public String toString() {
        return "Ray{" + head + " -> " + direction + "}";
    }
}
