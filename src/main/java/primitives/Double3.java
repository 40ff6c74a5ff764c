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

    public final double d1;
    public final double d2;
    public final double d3;

    public Double3(double d1, double d2, double d3) {
        this.d1 = d1;
        this.d2 = d2;
        this.d3 = d3;
    }

    /** The same value in all three components. */
    public Double3(double value) {
        this(value, value, value);
    }

    public Double3 add(Double3 other) {
        return new Double3(d1 + other.d1, d2 + other.d2, d3 + other.d3);
    }

    public Double3 subtract(Double3 other) {
        return new Double3(d1 - other.d1, d2 - other.d2, d3 - other.d3);
    }

    public Double3 scale(double factor) {
        return new Double3(d1 * factor, d2 * factor, d3 * factor);
    }

    /** Component-wise product. */
    public Double3 product(Double3 other) {
        return new Double3(d1 * other.d1, d2 * other.d2, d3 * other.d3);
    }

    /** Component-wise division by a scalar. */
    public Double3 reduce(double divisor) {
        return new Double3(d1 / divisor, d2 / divisor, d3 / divisor);
    }

    /** Whether every component is below {@code limit}. */
    public boolean lowerThan(double limit) {
        return d1 < limit && d2 < limit && d3 < limit;
    }

    /** Whether every component is exactly zero. */
    public boolean isZero() {
        return d1 == 0 && d2 == 0 && d3 == 0;
    }

    /** The largest component. */
    public double max() {
        return Math.max(d1, Math.max(d2, d3));
    }

    /** Throws unless every component lies in {@code [min, max]}, naming the parameter. */
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
