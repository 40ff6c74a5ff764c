package primitives;

/**
 * An immutable, non-zero direction in 3D space.
 *
 * <p>The zero vector is an error (it has no direction), and so is the cross product of parallel vectors.
 * {@link #normalize()} and {@link #length()} sum the squares of the components directly when they are in range, and
 * otherwise scale them by a power of two first (an exact scaling, so the result is the same as the direct sum would
 * be in unbounded range): they neither overflow for huge vectors nor underflow for tiny ones, and (1e-200,1e-200,
 * 1e-200) and (1e200,1e200,1e200) both give 1/sqrt(3) per component.
 */
public final class Vector extends Point {
    /** The unit vector along x. */
    public static final Vector AXIS_X = new Vector(1, 0, 0);
    /** The unit vector along y. */
    public static final Vector AXIS_Y = new Vector(0, 1, 0);
    /** The unit vector along z. */
    public static final Vector AXIS_Z = new Vector(0, 0, 1);

    /**
     * A vector of the given components.
     *
     * @param x the x component, finite
     * @param y the y component, finite
     * @param z the z component, finite
     * @throws IllegalArgumentException if a component is not finite or all three are zero
     */
    public Vector(double x, double y, double z) {
        super(x, y, z);
        if (x == 0 && y == 0 && z == 0) {
            throw new IllegalArgumentException("vector must not be zero: a zero vector has no direction");
        }
    }

    /**
     * A vector from a triple of components.
     *
     * @param xyz the components x, y, z as {@code d1}, {@code d2}, {@code d3}; finite, not all zero
     */
    public Vector(Double3 xyz) {
        this(xyz.d1, xyz.d2, xyz.d3);
    }

    @Override
    public Vector add(Vector other) {
        return new Vector(x + other.x, y + other.y, z + other.z);
    }

    /**
     * This vector minus {@code other}; an error if they are equal.
     *
     * @param other the vector subtracted
     * @return a new vector
     * @throws IllegalArgumentException if the vectors are equal (a zero vector)
     */
    public Vector subtract(Vector other) {
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /**
     * This vector times {@code factor}; an error if the factor is zero.
     *
     * @param factor the factor, non-zero
     * @return a new vector
     * @throws IllegalArgumentException if {@code factor} is zero
     */
    public Vector scale(double factor) {
        return new Vector(x * factor, y * factor, z * factor);
    }

    /**
     * The dot product.
     *
     * @param other the other vector
     * @return the sum of the products of the components
     */
    public double dotProduct(Vector other) {
        return x * other.x + y * other.y + z * other.z;
    }

    /**
     * The cross product, computed with {@link Util#differenceOfProducts} so that nearly parallel vectors do not
     * lose their small result to cancellation. Parallel vectors are an error.
     *
     * @param other the other vector, not parallel to this one
     * @return a new vector perpendicular to both
     * @throws IllegalArgumentException if the vectors are parallel
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

    /**
     * The squared length (cheaper than {@link #length()}, but it may overflow or underflow).
     *
     * @return {@code x*x + y*y + z*z}
     */
    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    /**
     * The length, computed without overflow or underflow.
     *
     * @return the Euclidean length
     */
    public double length() {
        return length(x, y, z);
    }

    /**
     * The length of (x, y, z), exactly as {@link #length()} computes it.
     *
     * @param x the x component
     * @param y the y component
     * @param z the z component, not all three zero
     * @return the Euclidean length
     */
    public static double length(double x, double y, double z) {
        double m = largestMagnitude(x, y, z);
        if (squaresInRange(m)) return Math.sqrt(x * x + y * y + z * z);
        int shift = exponentShift(m);
        double sx = Math.scalb(x, shift), sy = Math.scalb(y, shift), sz = Math.scalb(z, shift);
        return Math.scalb(Math.sqrt(sx * sx + sy * sy + sz * sz), -shift);
    }

    /**
     * Whether the squares of components at most {@code m} in magnitude (the largest of them) can be summed without
     * overflow and without losing precision to underflow (smaller components may underflow; they do not count).
     */
    private static boolean squaresInRange(double m) {
        return m >= 0x1p-500 && m <= 0x1p500;
    }

    /** The power of two that brings a largest component {@code m} out of range near 1 (an exact scaling). */
    private static int exponentShift(double m) {
        return -Math.getExponent(m);
    }

    /**
     * The unit vector in this direction, computed without overflow or underflow.
     *
     * @return a new unit vector
     */
    public Vector normalize() {
        double f = unitFactor(x, y, z);
        if (f > 0) return new Vector(x * f, y * f, z * f);
        return new Vector(unitComponent(x, x, y, z), unitComponent(y, x, y, z), unitComponent(z, x, y, z));
    }

    /**
     * What {@link #normalize()} multiplies the components of (x, y, z) by, {@code 1 / sqrt(x^2 + y^2 + z^2)}, where
     * it does: when the largest magnitude lies in [2^-500, 2^500] (the squares are in range) and at least two
     * components are non-zero. Otherwise 0, and the unit vector's components are {@link #unitComponent}'s. Together
     * they give {@code normalize()}'s values bit for bit without allocating, for hot paths.
     *
     * @param x the x component
     * @param y the y component
     * @param z the z component, not all three zero
     * @return the factor, or 0 where {@link #unitComponent} applies
     */
    public static double unitFactor(double x, double y, double z) {
        double m = largestMagnitude(x, y, z);
        if (!squaresInRange(m) || onAxis(x, y, z)) return 0;
        return 1 / Math.sqrt(x * x + y * y + z * z);
    }

    /**
     * Component {@code c} of the unit vector along (x, y, z), as {@link #normalize()} computes it: along an axis
     * exactly 1 or -1 and signed zeros (the product with a rounded inverse length may not be); out of range the
     * components are first scaled by a power of two, which is exact, so the result is the one the direct formula
     * would give with unbounded exponents.
     *
     * @param c the component wanted: {@code x}, {@code y} or {@code z}
     * @param x the x component
     * @param y the y component
     * @param z the z component, not all three zero
     * @return that component of the unit vector
     */
    public static double unitComponent(double c, double x, double y, double z) {
        if (onAxis(x, y, z)) return Math.signum(c);
        double m = largestMagnitude(x, y, z);
        int shift = squaresInRange(m) ? 0 : exponentShift(m);
        double sx = Math.scalb(x, shift), sy = Math.scalb(y, shift), sz = Math.scalb(z, shift);
        return Math.scalb(c, shift) * (1 / Math.sqrt(sx * sx + sy * sy + sz * sz));
    }

    /** Whether at most one of the components is non-zero. */
    private static boolean onAxis(double x, double y, double z) {
        return (x == 0 ? 1 : 0) + (y == 0 ? 1 : 0) + (z == 0 ? 1 : 0) >= 2;
    }

    /**
     * The component-wise absolute value.
     *
     * @return a new vector of the absolute components
     */
    public Vector abs() {
        return new Vector(Math.abs(x), Math.abs(y), Math.abs(z));
    }

    /** The largest magnitude of the three components. */
    private static double largestMagnitude(double x, double y, double z) {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /**
     * Some unit vector perpendicular to this unit vector, by the branchless construction of Duff et al. 2017
     * ("Building an Orthonormal Basis, Revisited"). Stable for every direction, including negative zero z.
     *
     * @return a new unit vector perpendicular to this one
     */
    public Vector perpendicular() {
        double sign = Math.copySign(1.0, z);
        double a = -1.0 / (sign + z);
        double b = x * y * a;
        return new Vector(1.0 + sign * x * x * a, sign * b, -sign * x);
    }
}
