package primitives;

import java.util.Arrays;

/**
 * An invertible affine map of space: {@code p -> M p + t}, with its inverse computed once. Transforms place
 * instances of a prototype geometry ({@code geometries.Instance}); they compose with {@link #then}, so
 * {@code Transform.scale(2).then(Transform.rotateZ(90)).then(Transform.translate(10, 0, 0))} scales first, then
 * rotates, then translates.
 *
 * <p>Rotations by whole multiples of 90 degrees use exact sines and cosines (0 and 1, not 6e-17), so a rotated
 * axis-aligned model stays exactly axis-aligned. A transform must be finite and invertible: a zero scale or a
 * singular matrix is rejected with the reason.
 */
public final class Transform {
    /** The map that leaves every point where it is. */
    public static final Transform IDENTITY = new Transform(new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});

    /** Row-major 3 x 4: the linear part M in columns 0..2, the translation t in column 3. */
    private final double[] m;

    private final double[] inverse;

    private Transform(double[] m) {
        for (int i = 0; i < 12; i++) {
            if (!Double.isFinite(m[i])) {
                throw new IllegalArgumentException("a transform must be finite, but entry (" + i / 4 + ", " + i % 4
                        + ") of its matrix was " + m[i]);
            }
        }
        this.m = m;
        this.inverse = invert(m);
    }

    /**
     * The transform of a row-major 3 x 4 matrix: rows {@code [m00 m01 m02 tx]}, {@code [m10 m11 m12 ty]},
     * {@code [m20 m21 m22 tz]}.
     *
     * @param rowMajor twelve finite numbers whose 3 x 3 part is invertible
     * @return the transform
     * @throws IllegalArgumentException if the array is not twelve finite numbers or the matrix is singular
     */
    public static Transform ofMatrix(double... rowMajor) {
        Util.requireNonNull(rowMajor, "transform matrix");
        if (rowMajor.length != 12) {
            throw new IllegalArgumentException(
                    "a transform matrix has 3 rows of 4 numbers (12 in all), but " + rowMajor.length + " were given");
        }
        return new Transform(rowMajor.clone());
    }

    /**
     * A translation.
     *
     * @param x the offset along x
     * @param y the offset along y
     * @param z the offset along z
     * @return the transform moving every point by (x, y, z)
     */
    public static Transform translate(double x, double y, double z) {
        return new Transform(new double[] {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z});
    }

    /**
     * A translation.
     *
     * @param offset the offset; not null
     * @return the transform moving every point by {@code offset}
     */
    public static Transform translate(Vector offset) {
        Util.requireNonNull(offset, "translation");
        return translate(offset.x, offset.y, offset.z);
    }

    /**
     * A uniform scale about the origin.
     *
     * @param factor the scale, finite and non-zero (negative mirrors through the origin)
     * @return the scaling transform
     */
    public static Transform scale(double factor) {
        return scale(factor, factor, factor);
    }

    /**
     * A scale about the origin, axis by axis.
     *
     * @param sx the scale along x, finite and non-zero (negative mirrors)
     * @param sy the scale along y, finite and non-zero
     * @param sz the scale along z, finite and non-zero
     * @return the scaling transform
     */
    public static Transform scale(double sx, double sy, double sz) {
        if (sx == 0 || sy == 0 || sz == 0) {
            throw new IllegalArgumentException(
                    "a scale must be non-zero on every axis (it would flatten space), but was " + sx + ", " + sy + ", "
                            + sz);
        }
        return new Transform(new double[] {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0});
    }

    /**
     * A rotation about the x axis, counter-clockwise seen from +x.
     *
     * @param degrees the angle in degrees
     * @return the rotation
     */
    public static Transform rotateX(double degrees) {
        return rotate(Vector.AXIS_X, degrees);
    }

    /**
     * A rotation about the y axis, counter-clockwise seen from +y.
     *
     * @param degrees the angle in degrees
     * @return the rotation
     */
    public static Transform rotateY(double degrees) {
        return rotate(Vector.AXIS_Y, degrees);
    }

    /**
     * A rotation about the z axis, counter-clockwise seen from +z.
     *
     * @param degrees the angle in degrees
     * @return the rotation
     */
    public static Transform rotateZ(double degrees) {
        return rotate(Vector.AXIS_Z, degrees);
    }

    /**
     * A rotation about an axis through the origin (Rodrigues' formula), counter-clockwise seen from the axis tip.
     *
     * @param axis the axis, any length; not null
     * @param degrees the angle in degrees, finite
     * @return the rotation
     */
    public static Transform rotate(Vector axis, double degrees) {
        Util.requireNonNull(axis, "rotation axis");
        Util.requireFinite(degrees, "rotation angle");
        Vector a = axis.normalize();
        double sin, cos;
        double quarterTurns = degrees / 90;
        if (quarterTurns == Math.rint(quarterTurns)) {
            // Exact for whole quarter turns, so a rotated axis-aligned model stays axis-aligned.
            int q = (int) Math.floorMod((long) quarterTurns, 4L);
            sin = q == 1 ? 1 : q == 3 ? -1 : 0;
            cos = q == 0 ? 1 : q == 2 ? -1 : 0;
        } else {
            double radians = Math.toRadians(degrees);
            sin = Math.sin(radians);
            cos = Math.cos(radians);
        }
        double x = a.x, y = a.y, z = a.z, c1 = 1 - cos;
        return new Transform(new double[] {
            cos + x * x * c1,
            x * y * c1 - z * sin,
            x * z * c1 + y * sin,
            0,
            y * x * c1 + z * sin,
            cos + y * y * c1,
            y * z * c1 - x * sin,
            0,
            z * x * c1 - y * sin,
            z * y * c1 + x * sin,
            cos + z * z * c1,
            0
        });
    }

    /**
     * This transform followed by {@code next}: the composite applies this one first.
     *
     * @param next the transform applied second; not null
     * @return {@code next} after this
     */
    public Transform then(Transform next) {
        Util.requireNonNull(next, "next transform");
        return new Transform(multiply(next.m, m));
    }

    /**
     * The inverse map.
     *
     * @return the transform undoing this one
     */
    public Transform inverse() {
        return new Transform(inverse.clone());
    }

    /**
     * The image of a point.
     *
     * @param p the point; not null
     * @return {@code M p + t}
     */
    public Point apply(Point p) {
        Util.requireNonNull(p, "point");
        return new Point(
                m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
                m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
    }

    /**
     * The image of a direction (translation does not apply).
     *
     * @param v the vector; not null
     * @return {@code M v}
     */
    public Vector applyToVector(Vector v) {
        Util.requireNonNull(v, "vector");
        return new Vector(
                m[0] * v.x + m[1] * v.y + m[2] * v.z,
                m[4] * v.x + m[5] * v.y + m[6] * v.z,
                m[8] * v.x + m[9] * v.y + m[10] * v.z);
    }

    /**
     * The image of a surface normal: the inverse transpose keeps it perpendicular to the transformed surface.
     *
     * @param n the normal; not null
     * @return the unit normal of the transformed surface, on the same side of it as {@code n}
     */
    public Vector applyToNormal(Vector n) {
        Util.requireNonNull(n, "normal");
        double[] i = inverse;
        return new Vector(
                        i[0] * n.x + i[4] * n.y + i[8] * n.z,
                        i[1] * n.x + i[5] * n.y + i[9] * n.z,
                        i[2] * n.x + i[6] * n.y + i[10] * n.z)
                .normalize();
    }

    /**
     * The determinant of the linear part: the volume scale, negative for a mirroring transform.
     *
     * @return the determinant
     */
    public double determinant() {
        return determinant(m);
    }

    /**
     * Whether this transform only moves: its linear part is exactly the identity (directions and lengths are kept).
     *
     * @return true for a pure translation (the identity included)
     */
    public boolean isTranslation() {
        return m[0] == 1
                && m[1] == 0
                && m[2] == 0
                && m[4] == 0
                && m[5] == 1
                && m[6] == 0
                && m[8] == 0
                && m[9] == 0
                && m[10] == 1;
    }

    /**
     * The row-major 3 x 4 matrix (a copy).
     *
     * @return twelve numbers: three rows of the linear part and the translation
     */
    public double[] toMatrix() {
        return m.clone();
    }

    /**
     * The inverse's row-major 3 x 4 matrix (a copy).
     *
     * @return twelve numbers of the inverse map
     */
    public double[] toInverseMatrix() {
        return inverse.clone();
    }

    private static double[] multiply(double[] a, double[] b) {
        double[] r = new double[12];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                double sum = col == 3 ? a[4 * row + 3] : 0;
                for (int k = 0; k < 3; k++) sum += a[4 * row + k] * b[4 * k + col];
                r[4 * row + col] = sum;
            }
        }
        return r;
    }

    private static double determinant(double[] m) {
        return m[0] * (m[5] * m[10] - m[6] * m[9])
                - m[1] * (m[4] * m[10] - m[6] * m[8])
                + m[2] * (m[4] * m[9] - m[5] * m[8]);
    }

    /** The inverse by cofactors; singular (or numerically singular) matrices are rejected. */
    private static double[] invert(double[] m) {
        double det = determinant(m);
        double scale = 0;
        for (int row = 0; row < 3; row++) {
            scale = Math.max(scale, Math.abs(m[4 * row]) + Math.abs(m[4 * row + 1]) + Math.abs(m[4 * row + 2]));
        }
        // A determinant tiny against the matrix's size means a map that (nearly) flattens space.
        if (!(Math.abs(det) > 1e-12 * scale * scale * scale)) {
            throw new IllegalArgumentException("a transform must be invertible, but its 3 x 3 part "
                    + Arrays.toString(new double[] {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]})
                    + " has determinant " + det + " (it flattens space)");
        }
        double inv = 1 / det;
        double[] r = new double[12];
        r[0] = (m[5] * m[10] - m[6] * m[9]) * inv;
        r[1] = (m[2] * m[9] - m[1] * m[10]) * inv;
        r[2] = (m[1] * m[6] - m[2] * m[5]) * inv;
        r[4] = (m[6] * m[8] - m[4] * m[10]) * inv;
        r[5] = (m[0] * m[10] - m[2] * m[8]) * inv;
        r[6] = (m[2] * m[4] - m[0] * m[6]) * inv;
        r[8] = (m[4] * m[9] - m[5] * m[8]) * inv;
        r[9] = (m[1] * m[8] - m[0] * m[9]) * inv;
        r[10] = (m[0] * m[5] - m[1] * m[4]) * inv;
        for (int row = 0; row < 3; row++) {
            r[4 * row + 3] = -(r[4 * row] * m[3] + r[4 * row + 1] * m[7] + r[4 * row + 2] * m[11]);
        }
        return r;
    }

    @Override
    public boolean equals(Object obj) {
        return obj instanceof Transform other && Arrays.equals(m, other.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        return "Transform" + Arrays.toString(m);
    }
}
