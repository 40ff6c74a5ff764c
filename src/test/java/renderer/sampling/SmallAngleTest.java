package renderer.sampling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class SmallAngleTest {
    /** Within two ulps of the result (Math's own are within one of the exact value) over the whole quarter range. */
    @Test
    void agreesWithMathWithinTwoUlps() {
        SplittableRandom random = new SplittableRandom(20261126);
        for (int i = 0; i < 200_000; i++) {
            double x = (2 * random.nextDouble() - 1) * Math.PI / 4;
            if (i % 4 == 0) x *= Math.scalb(1.0, -random.nextInt(60)); // small angles too
            assertNear(Math.sin(x), SmallAngle.sin(x), "sin", x);
            assertNear(Math.cos(x), SmallAngle.cos(x), "cos", x);
        }
        for (double x : new double[] {Math.PI / 4, -Math.PI / 4, Math.nextDown(Math.PI / 4), 0.0, -0.0}) {
            assertNear(Math.sin(x), SmallAngle.sin(x), "sin", x);
            assertNear(Math.cos(x), SmallAngle.cos(x), "cos", x);
        }
    }

    @Test
    void exactAtZeroAndOdd() {
        assertEquals(1.0, SmallAngle.cos(0));
        assertEquals(0.0, SmallAngle.sin(0));
        assertEquals(-SmallAngle.sin(0.3), SmallAngle.sin(-0.3), "odd");
        assertEquals(SmallAngle.cos(0.3), SmallAngle.cos(-0.3), "even");
    }

    private static void assertNear(double expected, double actual, String name, double x) {
        assertTrue(
                Math.abs(expected - actual) <= 2 * Math.ulp(expected),
                name + "(" + x + "): " + actual + " against Math's " + expected);
    }
}
