package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Unit tests for {@link Vector}, including the numerically hard cases of normalize and the cross product. */
class VectorTest {
    private static final double DELTA = 1e-12;
    private final Vector v1 = new Vector(1, 2, 3);
    private final Vector v2 = new Vector(-2, -4, -6); // parallel to v1, opposite
    private final Vector v3 = new Vector(0, 3, -2); // orthogonal to v1

    @Test
    void zeroVectorIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Vector(0, 0, 0));
        assertTrue(e.getMessage().contains("zero"), e.getMessage());
        // -0.0 is still zero
        assertThrows(IllegalArgumentException.class, () -> new Vector(-0.0, 0.0, -0.0));
        assertThrows(IllegalArgumentException.class, () -> new Vector(Double3.ZERO));
        // BVA: the smallest non-zero component is a valid direction
        assertEquals(Double.MIN_VALUE, new Vector(0, 0, Double.MIN_VALUE).z);
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY})
    void nonFiniteVectorIsRejected(double bad) {
        assertThrows(IllegalArgumentException.class, () -> new Vector(bad, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new Vector(1, bad, 1));
        assertThrows(IllegalArgumentException.class, () -> new Vector(1, 1, bad));
    }

    @Test
    void add() {
        // EP: general vectors
        assertEquals(new Vector(-1, -2, -3), v1.add(v2));
        // BVA: v + (-v) is the zero vector: an error
        assertThrows(IllegalArgumentException.class, () -> v1.add(new Vector(-1, -2, -3)));
    }

    @Test
    void subtract() {
        // EP: general vectors
        assertEquals(new Vector(3, 6, 9), v1.subtract(v2));
        // BVA: v - v is the zero vector: an error
        assertThrows(IllegalArgumentException.class, () -> v1.subtract(v1));
    }

    @Test
    void scale() {
        // EP: positive, negative and fractional factors
        assertEquals(new Vector(2, 4, 6), v1.scale(2));
        assertEquals(v2, v1.scale(-2));
        assertEquals(new Vector(0.5, 1, 1.5), v1.scale(0.5));
        // BVA: a zero factor gives the zero vector: an error
        assertThrows(IllegalArgumentException.class, () -> v1.scale(0));
    }

    @Test
    void dotProduct() {
        // EP: general vectors (1*-2 + 2*-4 + 3*-6 = -28)
        assertEquals(-28, v1.dotProduct(v2), DELTA);
        // BVA: orthogonal vectors
        assertEquals(0, v1.dotProduct(v3), DELTA);
        // BVA: a unit vector with itself
        assertEquals(1, Vector.AXIS_X.dotProduct(Vector.AXIS_X));
    }

    @Test
    void crossProduct() {
        // EP: orthogonal vectors v1 x v3: |v1 x v3| = |v1| |v3| and the result is orthogonal to both
        Vector vr = v1.crossProduct(v3);
        assertEquals(v1.length() * v3.length(), vr.length(), DELTA);
        assertEquals(0, vr.dotProduct(v1), DELTA);
        assertEquals(0, vr.dotProduct(v3), DELTA);
        // The exact value: (2*-2 - 3*3, 3*0 - 1*-2, 1*3 - 2*0) = (-13, 2, 3)
        assertEquals(new Vector(-13, 2, 3), vr);
        // EP: anti-commutative
        assertEquals(vr.scale(-1), v3.crossProduct(v1));
        // Right-handed axes
        assertEquals(Vector.AXIS_Z, Vector.AXIS_X.crossProduct(Vector.AXIS_Y));
        assertEquals(Vector.AXIS_X, Vector.AXIS_Y.crossProduct(Vector.AXIS_Z));
        assertEquals(Vector.AXIS_Y, Vector.AXIS_Z.crossProduct(Vector.AXIS_X));
        // EP: non-orthogonal, non-parallel: |a x b| = |a||b| sin(theta), here 45 degrees
        Vector a = new Vector(1, 0, 0), b = new Vector(1, 1, 0);
        assertEquals(Math.sqrt(2) * Math.sqrt(0.5), a.crossProduct(b).length(), DELTA);
    }

    @Test
    void crossProductOfParallelVectorsIsAnError() {
        // BVA: opposite directions
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(v2));
        assertTrue(e.getMessage().contains("parallel"), e.getMessage());
        // BVA: same direction, different length
        assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(v1.scale(3)));
        // BVA: the vector with itself
        assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(v1));
    }

    @Test
    void crossProductOfNearlyParallelVectorsIsAccurate() {
        // (1, 1, 1) x (1, 1, 1 + e) = (e, -e, 0) exactly; a naive product loses nothing here either,
        // but with 1 + e not representable exactly in the products the FMA form keeps the small result.
        double e = Math.ulp(1.0);
        Vector a = new Vector(1, 1, 1), b = new Vector(1, 1, 1 + e);
        Vector c = a.crossProduct(b);
        assertEquals(e, c.x, 0);
        assertEquals(-e, c.y, 0);
        assertEquals(0, c.z, 0);
        // Nearly parallel with products that round: (0.1, 0.2, 0.3) x (0.1, 0.2, 0.3 + tiny)
        Vector p = new Vector(0.1, 0.2, 0.3);
        Vector q = new Vector(0.1, 0.2, Math.nextUp(0.3));
        Vector r = p.crossProduct(q);
        double u = Math.ulp(0.3);
        // exact: (0.2 u, -0.1 u, 0) up to the representation of 0.1 and 0.2
        assertEquals(0.2 * u, r.x, 1e-3 * u);
        assertEquals(-0.1 * u, r.y, 1e-3 * u);
        assertEquals(0, r.z, 1e-3 * u);
    }

    @Test
    void lengthAndLengthSquared() {
        assertEquals(14, v1.lengthSquared(), DELTA);
        assertEquals(5, new Vector(0, 3, 4).length(), DELTA);
        assertEquals(Math.sqrt(14), v1.length(), DELTA);
        // BVA: components at the extremes of the range do not overflow or underflow
        assertEquals(5e200, new Vector(0, 3e200, 4e200).length(), 5e200 * DELTA);
        assertEquals(5e-200, new Vector(0, 3e-200, 4e-200).length(), 5e-200 * DELTA);
        assertEquals(Double.MAX_VALUE, new Vector(Double.MAX_VALUE, 0, 0).length());
        assertEquals(Double.MIN_VALUE, new Vector(0, Double.MIN_VALUE, 0).length());
    }

    @Test
    void normalize() {
        Vector u = v1.normalize();
        // EP: unit length
        assertEquals(1, u.length(), DELTA);
        // same direction: parallel (cross product is zero) and pointing the same way
        assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(u));
        assertTrue(v1.dotProduct(u) > 0);
        assertEquals(1 / Math.sqrt(14), u.x, DELTA);
        assertEquals(2 / Math.sqrt(14), u.y, DELTA);
        assertEquals(3 / Math.sqrt(14), u.z, DELTA);
        // BVA: an axis vector is its own normalization, exactly
        assertEquals(Vector.AXIS_Y, new Vector(0, 42, 0).normalize());
        assertEquals(new Vector(0, 0, -1), new Vector(0, 0, -1e-300).normalize());
    }

    @ParameterizedTest
    @ValueSource(doubles = {1e-200, 1e200, Double.MIN_VALUE, Double.MAX_VALUE, 1e-308, 1, -1e-200, -1e200})
    void normalizeOfEqualComponentsIsOneOverSqrtThreeAtAnyScale(double c) {
        Vector u = new Vector(c, c, c).normalize();
        double expected = Math.copySign(1 / Math.sqrt(3), c);
        assertEquals(expected, u.x, 1e-15, "x of " + c);
        assertEquals(expected, u.y, 1e-15, "y of " + c);
        assertEquals(expected, u.z, 1e-15, "z of " + c);
        assertEquals(1, u.length(), 1e-15);
    }

    @Test
    void normalizeOfTheIssueCasesExactly() {
        // The two cases named by the issue, spelled out
        for (double c : new double[] {1e-200, 1e200}) {
            Vector u = new Vector(c, c, c).normalize();
            for (double component : new double[] {u.x, u.y, u.z}) {
                assertTrue(Double.isFinite(component) && component != 0, "component " + component);
                assertEquals(1 / Math.sqrt(3), component, 1e-15);
            }
        }
    }

    @Test
    void absAndPerpendicular() {
        assertEquals(new Vector(1, 2, 3), new Vector(-1, 2, -3).abs());
        for (Vector v : new Vector[] {
            Vector.AXIS_X,
            Vector.AXIS_Y,
            Vector.AXIS_Z,
            new Vector(0, 0, -1),
            new Vector(0, -0.0, -1),
            new Vector(1e-300, 0, -0.0).normalize(),
            v1.normalize(),
            v2.normalize()
        }) {
            Vector p = v.perpendicular();
            assertEquals(0, p.dotProduct(v), 1e-15, "perpendicular to " + v);
            assertEquals(1, p.length(), 1e-15, "unit for " + v);
        }
    }

    // ----------------------------------------------------------------- property-style, seeded

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 25).mapToObj(i -> Arguments.of(0xC0FFEEL + 7919 * i));
    }

    /** A vector with random signs and magnitudes spread over 10^-150 .. 10^150 per component. */
    static Vector randomVector(Random random) {
        double scale = Math.pow(10, random.nextInt(301) - 150);
        return new Vector(
                scale * (random.nextDouble() * 2 - 1),
                scale * (random.nextDouble() * 2 - 1),
                scale * (random.nextDouble() * 2 - 1));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void normalizedRandomVectorsAreUnitAndParallel(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 200; i++) {
            Vector v = randomVector(random);
            Vector u = v.normalize();
            String where = "seed " + seed + ", vector " + v;
            assertEquals(1, u.x * u.x + u.y * u.y + u.z * u.z, 1e-14, where);
            // same direction: each component keeps its sign and ratio
            double m = Math.max(Math.abs(v.x), Math.max(Math.abs(v.y), Math.abs(v.z)));
            double n = Math.max(Math.abs(u.x), Math.max(Math.abs(u.y), Math.abs(u.z)));
            assertEquals(v.x / m, u.x / n, 1e-14, where);
            assertEquals(v.y / m, u.y / n, 1e-14, where);
            assertEquals(v.z / m, u.z / n, 1e-14, where);
        }
    }

    /**
     * Out of the range where squares can be summed directly, normalize and length scale by a power of two, which is
     * exact: so the same direction at 2^-600, 1 or 2^600 times the size gives the same unit vector bit for bit, and
     * lengths in the same ratio, and a ray along it the same direction.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void powerOfTwoScalesChangeNeitherDirectionNorRelativeLength(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 200; i++) {
            Vector v =
                    new Vector(random.nextDouble() * 2 - 1, random.nextDouble() * 2 - 1, random.nextDouble() * 2 - 1);
            Vector u = v.normalize();
            for (int e : new int[] {-600, -520, 520, 600}) {
                Vector scaled = new Vector(Math.scalb(v.x, e), Math.scalb(v.y, e), Math.scalb(v.z, e));
                String where = "seed " + seed + ", " + v + " times 2^" + e;
                assertEquals(u, scaled.normalize(), where);
                assertEquals(Math.scalb(v.length(), e), scaled.length(), 0, where);
                assertEquals(u, new Ray(Point.ZERO, scaled).getDirection(), where);
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void crossProductOfRandomUnitVectorsIsOrthogonal(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 200; i++) {
            Vector a = randomVector(random).normalize();
            Vector b = randomVector(random).normalize();
            Vector c = a.crossProduct(b);
            String where = "seed " + seed + ", " + a + " x " + b;
            double cl = c.length();
            assertEquals(0, c.dotProduct(a) / cl, 1e-12, where);
            assertEquals(0, c.dotProduct(b) / cl, 1e-12, where);
            // |a x b|^2 + (a.b)^2 = 1 for unit vectors (Lagrange's identity)
            double ab = a.dotProduct(b);
            assertEquals(1, cl * cl + ab * ab, 1e-12, where);
        }
    }
}
