package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import java.util.function.IntToDoubleFunction;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class ConvergenceLawTest {
    private static final int PIXELS = 4096;

    static Stream<Double> exponents() {
        return Stream.of(1.0, 1.2, 1.5, 1.9);
    }

    /** Pixels refined from various counts, their MSE falling exactly as n^-alpha: the fit finds alpha. */
    @ParameterizedTest(name = "alpha {0}")
    @MethodSource("exponents")
    void fitsTheExponentThePassAchieved(double alpha) {
        double[] mse = new double[PIXELS];
        int[] done = new int[PIXELS];
        ConvergenceLaw law = planAndRefine(mse, done, refined -> alpha);
        law.fit(mse, done);
        assertEquals(alpha, law.alpha(), 1.0 / 128);
    }

    /**
     * A law that remembered a plan over random MSEs and counts, after a pass that refined two pixels in three (the
     * others are left out of a fit), the k-th of them falling as n^-{@code exponent(k)}; the pass's MSEs and counts in
     * {@code mse} and {@code done}.
     */
    private static ConvergenceLaw planAndRefine(double[] mse, int[] done, IntToDoubleFunction exponent) {
        SplittableRandom random = new SplittableRandom(7);
        for (int p = 0; p < PIXELS; p++) {
            mse[p] = random.nextDouble() * 10;
            done[p] = 1 + random.nextInt(4);
        }
        ConvergenceLaw law = new ConvergenceLaw(PIXELS);
        law.remember(mse, done);
        for (int p = 0, refined = 0; p < PIXELS; p++) {
            if (p % 3 == 0) continue;
            int now = done[p] * (2 + random.nextInt(7));
            mse[p] *= Math.pow((double) done[p] / now, exponent.applyAsDouble(refined++));
            done[p] = now;
        }
        return law;
    }

    @Test
    void staysWithinItsBoundsAndKeepsThePriorUntilAPassSaysMore() {
        ConvergenceLaw law = new ConvergenceLaw(PIXELS);
        double[] mse = new double[PIXELS];
        int[] done = new int[PIXELS];
        java.util.Arrays.fill(mse, 4);
        java.util.Arrays.fill(done, 1);
        law.fit(mse, done);
        assertEquals(ConvergenceLaw.PRIOR, law.alpha(), "nothing planned yet");
        law.remember(mse, done);
        done[0] = 8; // one refined pixel: too few to fit
        law.fit(mse, done);
        assertEquals(ConvergenceLaw.PRIOR, law.alpha(), "a handful of pixels refined");
        java.util.Arrays.fill(done, 8); // every pixel refined 8x, its error unchanged
        law.fit(mse, done);
        assertEquals(ConvergenceLaw.MIN, law.alpha(), "no faster than 1/n is assumed");
        java.util.Arrays.fill(mse, 0);
        law.fit(mse, done);
        assertEquals(ConvergenceLaw.MAX, law.alpha(), "converged to zero: the steepest law allowed");
    }

    @Test
    void tabulatesInversePowersOfTheCurrentExponent() {
        ConvergenceLaw law = new ConvergenceLaw(1);
        double[] powers = law.inversePowers(100);
        for (int n = 1; n <= 100; n++) assertEquals(Math.pow(n, -ConvergenceLaw.PRIOR), powers[n], 0.0);
    }
}
