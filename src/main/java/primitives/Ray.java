package primitives;

/**
 * A half-line: an origin and a unit direction.
 *
 * <p>Besides the user-facing {@link #getHead()} and {@link #getDirection()}, a ray carries the per-ray constants
 * that the intersection kernels need, computed once here instead of once per box or triangle: the raw
 * coordinates, the reciprocal direction for the slab test, and the axis permutation and shear of the watertight
 * triangle test (Woop, Benthin and Wald 2013).
 *
 * <p>A ray built with the constructor never changes, and computes its constants at once. The renderer traces
 * millions of rays per second through one {@link ReusableRay} per thread instead, which {@link ReusableRay#set}
 * points somewhere new for every ray: an {@link geometries.Intersectable} must not keep a reference to the ray it is
 * given beyond the call. A reusable ray computes the slab and shear constants when they are first read: a ray that
 * meets only spheres and planes never needs them (their three divisions were a tenth of a render of a sphere over a
 * plane), and a reusable ray stays with the one thread that sets it.
 */
public class Ray {
    /** Created on demand for reusable rays (the kernels read the raw coordinates below). */
    private Point head;

    private Vector direction;

    private double ox, oy, oz, dx, dy, dz;
    private double invDx, invDy, invDz;
    private int kx, ky, kz;
    private double shearX, shearY, shearZ;
    /** Whether the reciprocals, axes and shear above are those of the current direction. */
    private boolean derived;

    /**
     * A ray from {@code head} along {@code direction}, which is normalized here. A NaN or infinite origin or a
     * zero or NaN direction cannot be expressed by {@link Point} and {@link Vector}, so they are rejected there.
     *
     * @param head the ray's origin; not null
     * @param direction the ray's direction, any length; not null
     */
    public Ray(Point head, Vector direction) {
        Util.requireNonNull(head, "ray origin");
        Util.requireNonNull(direction, "ray direction");
        init(head.x, head.y, head.z, direction.x, direction.y, direction.z);
        derive();
        this.head = head;
    }

    /** For {@link ReusableRay}: along +z from the origin until it is first set. */
    Ray() {
        init(0, 0, 0, 0, 0, 1);
    }

    /**
     * Sets the origin and the direction from an origin and a direction that need not be unit: normalized exactly as
     * {@link Vector#normalize()} does, so a reusable ray and a constructed one along the same vector agree bit for bit.
     * The constants derived from the direction follow on first use.
     */
    final void init(double ox, double oy, double oz, double vx, double vy, double vz) {
        head = null;
        direction = null;
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        double dx, dy, dz;
        double f = Vector.unitFactor(vx, vy, vz);
        if (f > 0) {
            dx = vx * f;
            dy = vy * f;
            dz = vz * f;
        } else {
            dx = Vector.unitComponent(vx, vx, vy, vz);
            dy = Vector.unitComponent(vy, vx, vy, vz);
            dz = Vector.unitComponent(vz, vx, vy, vz);
        }
        this.dx = dx;
        this.dy = dy;
        this.dz = dz;
        derived = false;
    }

    /** Computes the reciprocal direction, the watertight test's axes and its shear from the direction. */
    private void derive() {
        derived = true;
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
        // 1/d[kz] is one of the reciprocals above; the shear's products with it round differently from quotients,
        // which does not matter to the watertight test: every triangle sees the same constants.
        shearZ = kz == 0 ? invDx : kz == 1 ? invDy : invDz;
        shearX = -component(kx) * shearZ;
        shearY = -component(ky) * shearZ;
    }

    /**
     * Sets this ray to {@code other}'s direction, with all the constants derived from it copied rather than computed
     * again, from a new origin (for {@link ReusableRay#setMoved}).
     */
    final void initMoved(Ray other, double ox, double oy, double oz) {
        head = null;
        direction = other.direction;
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        dx = other.dx;
        dy = other.dy;
        dz = other.dz;
        derived = other.derived;
        invDx = other.invDx;
        invDy = other.invDy;
        invDz = other.invDz;
        kx = other.kx;
        ky = other.ky;
        kz = other.kz;
        shearX = other.shearX;
        shearY = other.shearY;
        shearZ = other.shearZ;
    }

    private double component(int axis) {
        return axis == 0 ? dx : axis == 1 ? dy : dz;
    }

    /**
     * The origin.
     *
     * @return the ray's head (created on first use for rays set from coordinates)
     */
    public Point getHead() {
        if (head == null) head = new Point(ox, oy, oz);
        return head;
    }

    /**
     * The unit direction.
     *
     * @return the unit direction (created on first use for rays set from coordinates)
     */
    public Vector getDirection() {
        if (direction == null) direction = new Vector(dx, dy, dz);
        return direction;
    }

    /**
     * The point at distance {@code t} along the ray; {@code t = 0} is the head itself.
     *
     * @param t the distance along the ray from the head
     * @return the point {@code head + t direction}
     */
    public Point getPoint(double t) {
        return t == 0 ? getHead() : new Point(ox + t * dx, oy + t * dy, oz + t * dz);
    }

    /**
     * Origin x (the kernels read the coordinates one by one; {@link #getHead()} is the same point).
     *
     * @return the origin's x coordinate
     */
    public final double ox() {
        return ox;
    }

    /**
     * Origin y.
     *
     * @return the origin's y coordinate
     */
    public final double oy() {
        return oy;
    }

    /**
     * Origin z.
     *
     * @return the origin's z coordinate
     */
    public final double oz() {
        return oz;
    }

    /**
     * Unit direction x (the components of {@link #getDirection()}).
     *
     * @return the unit direction's x component
     */
    public final double dx() {
        return dx;
    }

    /**
     * Unit direction y.
     *
     * @return the unit direction's y component
     */
    public final double dy() {
        return dy;
    }

    /**
     * Unit direction z.
     *
     * @return the unit direction's z component
     */
    public final double dz() {
        return dz;
    }

    /**
     * {@code 1 / dx}: infinite for a zero component (the slab test handles it).
     *
     * @return the inverse of the direction's x component
     */
    public final double invDx() {
        if (!derived) derive();
        return invDx;
    }

    /**
     * {@code 1 / dy}: infinite for a zero component.
     *
     * @return the inverse of the direction's y component
     */
    public final double invDy() {
        if (!derived) derive();
        return invDy;
    }

    /**
     * {@code 1 / dz}: infinite for a zero component.
     *
     * @return the inverse of the direction's z component
     */
    public final double invDz() {
        if (!derived) derive();
        return invDz;
    }

    /**
     * The watertight triangle test's axis permutation: {@code kz} is the axis of the largest direction component.
     *
     * @return the axis (0, 1 or 2) mapped to x
     */
    public final int kx() {
        if (!derived) derive();
        return kx;
    }

    /**
     * The watertight triangle test's axis mapped to y.
     *
     * @return the axis (0, 1 or 2) mapped to y
     */
    public final int ky() {
        if (!derived) derive();
        return ky;
    }

    /**
     * The watertight triangle test's axis mapped to z: the axis of the largest direction component.
     *
     * @return the axis (0, 1 or 2) mapped to z
     */
    public final int kz() {
        if (!derived) derive();
        return kz;
    }

    /**
     * The watertight triangle test's shear constants: {@code -d[kx]/d[kz]}, {@code -d[ky]/d[kz]}, {@code 1/d[kz]}.
     *
     * @return {@code -d[kx]/d[kz]}
     */
    public final double shearX() {
        if (!derived) derive();
        return shearX;
    }

    /**
     * The watertight triangle test's shear constant {@code -d[ky]/d[kz]}.
     *
     * @return {@code -d[ky]/d[kz]}
     */
    public final double shearY() {
        if (!derived) derive();
        return shearY;
    }

    /**
     * The watertight triangle test's shear constant {@code 1/d[kz]}.
     *
     * @return {@code 1/d[kz]}
     */
    public final double shearZ() {
        if (!derived) derive();
        return shearZ;
    }

    @Override
    public boolean equals(Object obj) {
        return obj instanceof Ray other
                && Double.compare(ox, other.ox) == 0
                && Double.compare(oy, other.oy) == 0
                && Double.compare(oz, other.oz) == 0
                && Double.compare(dx, other.dx) == 0
                && Double.compare(dy, other.dy) == 0
                && Double.compare(dz, other.dz) == 0;
    }

    @Override
    public int hashCode() {
        return getHead().hashCode() * 31 + getDirection().hashCode();
    }

    @Override
    public String toString() {
        return "Ray{" + getHead() + " -> " + getDirection() + "}";
    }
}
