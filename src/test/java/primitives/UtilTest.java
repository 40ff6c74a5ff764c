package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Unit tests for {@link Util}. */
class UtilTest {

    @Test
    void gammaMatchesItsDefinition() {
        double eps = Math.ulp(1.0) / 2;
        assertEquals(eps, Util.MACHINE_EPSILON);
        assertEquals(0, Util.gamma(0));
        assertEquals(3 * eps / (1 - 3 * eps), Util.gamma(3));
        // monotone and slightly above n * eps
        assertTrue(Util.gamma(5) > 5 * eps);
        assertTrue(Util.gamma(5) < Util.gamma(6));
    }

    @Test
    void differenceOfProductsIsExactWhereTheNaiveFormulaCancels() {
        // a*b and c*d round to the same double but differ exactly: the naive difference is 0
        double a = 1 + Math.ulp(1.0), b = 1 - Math.ulp(1.0) / 2;
        double c = 1, d = 1;
        // exact: (1 + 2^-52)(1 - 2^-53) - 1 = 2^-52 - 2^-53 - 2^-105 = 2^-53 - 2^-105
        double exact = Math.scalb(1.0, -53) - Math.scalb(1.0, -105);
        assertEquals(exact, Util.differenceOfProducts(a, b, c, d), Math.ulp(exact));
        // exact zero stays exactly zero
        assertEquals(0, Util.differenceOfProducts(0.1, 0.3, 0.3, 0.1));
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 10).mapToObj(i -> Arguments.of(0xD1FFL * (i + 1)));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void differenceOfProductsHasTheSignOfTheExactValue(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 500; i++) {
            double a = random.nextDouble() * 2 - 1, b = random.nextDouble() * 2 - 1;
            // c*d close to a*b so that the difference nearly cancels
            double c = a * (1 + (random.nextInt(5) - 2) * Math.ulp(1.0)), d = b;
            BigDecimal exact = new BigDecimal(a)
                    .multiply(new BigDecimal(b))
                    .subtract(new BigDecimal(c).multiply(new BigDecimal(d)));
            double got = Util.differenceOfProducts(a, b, c, d);
            String where = "seed " + seed + ": " + a + "*" + b + " - " + c + "*" + d;
            assertEquals(exact.signum(), (int) Math.signum(got), where);
            if (exact.signum() != 0) {
                double relative = Math.abs(exact.subtract(new BigDecimal(got)).doubleValue() / exact.doubleValue());
                assertTrue(relative <= 2 * Math.ulp(1.0), where + " relative error " + relative);
            }
        }
    }

    @Test
    void isZero() {
        assertTrue(Util.isZero(0, 0));
        assertTrue(Util.isZero(1e-10, 1e-10)); // BVA: inclusive
        assertTrue(Util.isZero(-1e-10, 1e-10));
        assertFalse(Util.isZero(1.0001e-10, 1e-10));
        assertFalse(Util.isZero(Double.NaN, 1));
    }

    @Test
    void validators() {
        assertEquals(2.5, Util.requireFinite(2.5, "x"));
        assertEquals(1e-300, Util.requirePositive(1e-300, "x"));
        assertEquals(0, Util.requireNonNegative(0, "x"));
        assertEquals(1, Util.requireInRange(1, 0, 1, "x"));
        assertEquals(0, Util.requireInRange(0, 0, 1, "x"));
        String s = "s";
        assertSame(s, Util.requireNonNull(s, "x"));

        assertMessage(() -> Util.requireFinite(Double.NaN, "radius"), "radius", "NaN");
        assertMessage(() -> Util.requireFinite(Double.NEGATIVE_INFINITY, "radius"), "radius", "-Infinity");
        assertMessage(() -> Util.requirePositive(0, "radius"), "radius", "0.0");
        assertMessage(() -> Util.requirePositive(-1, "radius"), "radius", "-1.0");
        assertMessage(() -> Util.requirePositive(Double.NaN, "radius"), "radius", "NaN");
        assertMessage(() -> Util.requirePositive(Double.POSITIVE_INFINITY, "radius"), "radius", "Infinity");
        assertMessage(() -> Util.requireNonNegative(-1e-300, "kC"), "kC", "-1.0E-300");
        assertMessage(() -> Util.requireNonNegative(Double.NaN, "kC"), "kC", "NaN");
        assertMessage(() -> Util.requireInRange(1.5, 0, 1, "roughness"), "roughness", "1.5");
        assertMessage(() -> Util.requireInRange(Double.NaN, 0, 1, "roughness"), "roughness", "NaN");
        assertMessage(() -> Util.requireNonNull(null, "scene"), "scene", "null");
    }

    private static void assertMessage(Runnable action, String name, String value) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, action::run);
        assertTrue(e.getMessage().contains(name), e.getMessage());
        assertTrue(e.getMessage().contains(value), e.getMessage());
    }

    /**
     * The highlight's integer power against {@link Math#pow} (within an ulp of exact): within 2n ulps for seeded
     * bases in (0, 1] and exponents up to 1000, exact where the answer is, and 1 for the zeroth power.
     */
    @Test
    void integerPowerIsWithinTwoNUlpsOfMathPow() {
        Random random = new Random(0x5EED);
        for (int i = 0; i < 20_000; i++) {
            double x = 1 - random.nextDouble();
            int n = i < 1000 ? i : random.nextInt(1001);
            double expected = Math.pow(x, n);
            double tolerance = (2 * n + 1) * Math.ulp(expected);
            assertEquals(expected, Util.power(x, n), tolerance, x + "^" + n);
        }
        assertEquals(1, Util.power(0.3, 0));
        assertEquals(0.3, Util.power(0.3, 1));
        assertEquals(1024, Util.power(2, 10));
        assertEquals(0, Util.power(0, 7));
        assertEquals(1, Util.power(1, 999));
        assertEquals(-0.125, Util.power(-0.5, 3));
    }
}
