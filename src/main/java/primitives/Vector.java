package primitives;

/**
 * An immutable, non-zero direction in 3D space.
 *
 * <p>The zero vector is an error (it has no direction), and so is the cross product of parallel vectors.
 * {@link #normalize()} scales by the largest component first, so it neither overflows for huge vectors nor
 * underflows for tiny ones: (1e-200,1e-200,1e-200) and (1e200,1e200,1e200) both give 1/sqrt(3) per component.
 */
public final class Vector extends Point {
    public static final Vector AXIS_X = new Vector(1, 0, 0);
    public static final Vector AXIS_Y = new Vector(0, 1, 0);
    public static final Vector AXIS_Z = new Vector(0, 0, 1);

    public Vector(double x, double y, double z) {
        super(x, y, z);
        if (x == 0 && y == 0 && z == 0) {
            throw new IllegalArgumentException("vector must not be zero: a zero vector has no direction");
        }
    }

    /** A vector from a triple of components. */
    public Vector(Double3 xyz) {
        this(xyz.d1, xyz.d2, xyz.d3);
    }

    @Override
    public Vector add(Vector other) {
        return new Vector(x + other.x, y + other.y, z + other.z);
    }

    /** This vector minus {@code other}; an error if they are equal. */
    public Vector subtract(Vector other) {
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /** This vector times {@code factor}; an error if the factor is zero. */
    public Vector scale(double factor) {
        return new Vector(x * factor, y * factor, z * factor);
    }

    public double dotProduct(Vector other) {
        return x * other.x + y * other.y + z * other.z;
    }

    /**
     * The cross product, computed with {@link Util#differenceOfProducts} so that nearly parallel vectors do not
     * lose their small result to cancellation. Parallel vectors are an error.
     */
    public Vector crossProduct(Vector other) {
        double cx = Util.differenceOfProducts(y, other.z, z, other.y);
        double cy = Util.differenceOfProducts(z, other.x, x, other.z);
        double cz = Util.differenceOfProducts(x, other.y, y, other.x);
        if (cx == 0 && cy == 0 && cz == 0) {
            throw new IllegalArgumentException(
                    "cross product of parallel vectors " + this + " and " + other + " is the zero vector");
        }
        return new Vector(cx, cy, cz);
    }

    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    /** The length, computed without overflow or underflow. */
    public double length() {
        return length(x, y, z);
    }

    /** The length of (x, y, z), exactly as {@link #length()} computes it (scaled by the largest component first). */
    public static double length(double x, double y, double z) {
        double m = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        double sx = x / m;
        double sy = y / m;
        double sz = z / m;
        return m * Math.sqrt(sx * sx + sy * sy + sz * sz);
    }

    /** The unit vector in this direction, computed without overflow or underflow. */
    public Vector normalize() {
        // Scaling by the largest component first keeps the squares in range for any finite input.
        double m = maxAbsComponent();
        double sx = x / m;
        double sy = y / m;
        double sz = z / m;
        double inverseLength = 1 / Math.sqrt(sx * sx + sy * sy + sz * sz);
        return new Vector(sx * inverseLength, sy * inverseLength, sz * inverseLength);
    }

    /** The component-wise absolute value. */
    public Vector abs() {
        return new Vector(Math.abs(x), Math.abs(y), Math.abs(z));
    }

    private double maxAbsComponent() {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /**
     * Some unit vector perpendicular to this unit vector, by the branchless construction of Duff et al. 2017
     * ("Building an Orthonormal Basis, Revisited"). Stable for every direction, including negative zero z.
     */
    public Vector perpendicular() {
        double sign = Math.copySign(1.0, z);
        double a = -1.0 / (sign + z);
        double b = x * y * a;
        return new Vector(1.0 + sign * x * x * a, sign * b, -sign * x);
    }
}
