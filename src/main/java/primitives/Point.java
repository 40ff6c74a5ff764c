package primitives;

/**
 * An immutable point in 3D space. Coordinates must be finite: a NaN or infinite coordinate is rejected at
 * construction so it can never spread through a render.
 */
public class Point {
    /** The origin (0,0,0). */
    public static final Point ZERO = new Point(0, 0, 0);

    /** The x coordinate, finite. */
    public final double x;
    /** The y coordinate, finite. */
    public final double y;
    /** The z coordinate, finite. */
    public final double z;

    /**
     * A point of the given coordinates.
     *
     * @param x the x coordinate, finite
     * @param y the y coordinate, finite
     * @param z the z coordinate, finite
     * @throws IllegalArgumentException if a coordinate is NaN or infinite
     */
    public Point(double x, double y, double z) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z))) {
            throw new IllegalArgumentException(
                    "coordinates must be finite, but were (" + x + ", " + y + ", " + z + ")");
        }
        this.x = x;
        this.y = y;
        this.z = z;
    }

    /**
     * A point from a triple of coordinates.
     *
     * @param xyz the coordinates x, y, z as {@code d1}, {@code d2}, {@code d3}; each finite
     */
    public Point(Double3 xyz) {
        this(xyz.d1, xyz.d2, xyz.d3);
    }

    /**
     * The x coordinate.
     *
     * @return x, finite
     */
    public double getX() {
        return x;
    }

    /**
     * The y coordinate.
     *
     * @return y, finite
     */
    public double getY() {
        return y;
    }

    /**
     * The z coordinate.
     *
     * @return z, finite
     */
    public double getZ() {
        return z;
    }

    /**
     * This point moved by {@code vector}.
     *
     * @param vector the displacement
     * @return a new point
     */
    public Point add(Vector vector) {
        return new Point(x + vector.x, y + vector.y, z + vector.z);
    }

    /**
     * The vector from {@code other} to this point; an error if the points coincide.
     *
     * @param other the start point of the vector
     * @return the vector {@code this - other}
     * @throws IllegalArgumentException if the points coincide (a zero vector)
     */
    public Vector subtract(Point other) {
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /**
     * The squared distance to another point (cheaper than {@link #distance}).
     *
     * @param other the other point
     * @return the squared Euclidean distance
     */
    public double distanceSquared(Point other) {
        double dx = x - other.x;
        double dy = y - other.y;
        double dz = z - other.z;
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * The distance to another point.
     *
     * @param other the other point
     * @return the Euclidean distance
     */
    public double distance(Point other) {
        return Math.sqrt(distanceSquared(other));
    }

    /**
     * The coordinates as a triple.
     *
     * @return a new triple (x, y, z)
     */
    public Double3 toDouble3() {
        return new Double3(x, y, z);
    }

    /**
     * Coordinate {@code axis} (0 = x, 1 = y, 2 = z).
     *
     * @param axis 0 for x, 1 for y, 2 for z (any other value gives z)
     * @return the coordinate on that axis
     */
    public double get(int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    @Override
    public boolean equals(Object obj) {
        if (this == obj) return true;
        return obj instanceof Point other
                && obj.getClass() == getClass()
                && Double.compare(x, other.x) == 0
                && Double.compare(y, other.y) == 0
                && Double.compare(z, other.z) == 0;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(x) * 961 + Double.hashCode(y) * 31 + Double.hashCode(z);
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ", " + z + ")";
    }
}
