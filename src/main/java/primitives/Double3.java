package primitives;

/**
 * An immutable triple of doubles: the per-channel coefficients of materials (kD, kS, kR, kT) and the
 * storage behind {@link Color}. Arithmetic is component-wise.
 */
public final class Double3 {
    /** (0,0,0). */
    public static final Double3 ZERO = new Double3(0, 0, 0);
    /** (1,1,1). */
    public static final Double3 ONE = new Double3(1, 1, 1);

    /** The first component (red in colours). */
    public final double d1;
    /** The second component (green in colours). */
    public final double d2;
    /** The third component (blue in colours). */
    public final double d3;

    /**
     * A triple of the given components.
     *
     * @param d1 the first component
     * @param d2 the second component
     * @param d3 the third component
     */
    public Double3(double d1, double d2, double d3) {
        this.d1 = d1;
        this.d2 = d2;
        this.d3 = d3;
    }

    /**
     * The same value in all three components.
     *
     * @param value the value of all three components
     */
    public Double3(double value) {
        this(value, value, value);
    }

    /**
     * The component-wise sum.
     *
     * @param other the triple added
     * @return a new triple
     */
    public Double3 add(Double3 other) {
        return new Double3(d1 + other.d1, d2 + other.d2, d3 + other.d3);
    }

    /**
     * The component-wise difference.
     *
     * @param other the triple subtracted
     * @return a new triple
     */
    public Double3 subtract(Double3 other) {
        return new Double3(d1 - other.d1, d2 - other.d2, d3 - other.d3);
    }

    /**
     * This triple times a scalar.
     *
     * @param factor the factor of every component
     * @return a new triple
     */
    public Double3 scale(double factor) {
        return new Double3(d1 * factor, d2 * factor, d3 * factor);
    }

    /**
     * Component-wise product.
     *
     * @param other the triple multiplied by
     * @return a new triple
     */
    public Double3 product(Double3 other) {
        return new Double3(d1 * other.d1, d2 * other.d2, d3 * other.d3);
    }

    /**
     * Component-wise division by a scalar.
     *
     * @param divisor the divisor of every component
     * @return a new triple
     */
    public Double3 reduce(double divisor) {
        return new Double3(d1 / divisor, d2 / divisor, d3 / divisor);
    }

    /**
     * Whether every component is below {@code limit}.
     *
     * @param limit the exclusive upper bound
     * @return true when all three components are below {@code limit}
     */
    public boolean lowerThan(double limit) {
        return d1 < limit && d2 < limit && d3 < limit;
    }

    /**
     * Whether every component is exactly zero.
     *
     * @return true when all three components are 0
     */
    public boolean isZero() {
        return d1 == 0 && d2 == 0 && d3 == 0;
    }

    /**
     * The largest component.
     *
     * @return the maximum of the three components
     */
    public double max() {
        return Math.max(d1, Math.max(d2, d3));
    }

    /**
     * Throws unless every component lies in {@code [min, max]}, naming the parameter.
     *
     * @param min the smallest allowed value
     * @param max the largest allowed value
     * @param name the parameter's name in the message
     * @return this triple
     * @throws IllegalArgumentException if a component is outside {@code [min, max]} or NaN
     */
    public Double3 requireInRange(double min, double max, String name) {
        if (!(d1 >= min && d1 <= max && d2 >= min && d2 <= max && d3 >= min && d3 <= max)) {
            throw new IllegalArgumentException(
                    name + " components must be in [" + min + ", " + max + "], but was " + this);
        }
        return this;
    }

    @Override
    public boolean equals(Object obj) {
        return obj instanceof Double3 other
                && Double.compare(d1, other.d1) == 0
                && Double.compare(d2, other.d2) == 0
                && Double.compare(d3, other.d3) == 0;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(d1) * 961 + Double.hashCode(d2) * 31 + Double.hashCode(d3);
    }

    @Override
    public String toString() {
        return "(" + d1 + "," + d2 + "," + d3 + ")";
    }
}
