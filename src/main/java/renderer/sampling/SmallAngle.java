package renderer.sampling;

/**
 * Sine and cosine of angles within [-pi/4, pi/4], the only ones the concentric disk mapping needs, by their Taylor
 * polynomials: the first omitted term is below 5e-17, so each result lies within about one ulp of the exact value.
 *
 * <p>Why not {@link Math#sin} and {@link Math#cos}: they reduce arbitrary arguments and are calls into the JVM's
 * stubs, which cost a tenth of a warm progressive soft-shadow render (perf, the POV-Ray comparison scene). These are a
 * few multiply-adds that the JIT inlines, and plain Java arithmetic, the same on every JVM.
 */
final class SmallAngle {
    private SmallAngle() {}

    // (-1)^k / (2k + 1)! and (-1)^k / (2k)!
    private static final double S3 = -1.0 / 6, S5 = 1.0 / 120, S7 = -1.0 / 5040, S9 = 1.0 / 362880;
    private static final double S11 = -1.0 / 39916800, S13 = 1.0 / 6227020800.0, S15 = -1.0 / 1307674368000.0;
    private static final double C2 = -1.0 / 2, C4 = 1.0 / 24, C6 = -1.0 / 720, C8 = 1.0 / 40320;
    private static final double C10 = -1.0 / 3628800, C12 = 1.0 / 479001600, C14 = -1.0 / 87178291200.0;
    private static final double C16 = 1.0 / 20922789888000.0;

    /** The sine of {@code x}, for |x| at most pi/4. */
    static double sin(double x) {
        double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
        double low = (S3 + x2 * S5) + x4 * (S7 + x2 * S9);
        double high = (S11 + x2 * S13) + x4 * S15;
        return x + x * x2 * (low + x8 * high);
    }

    /** The cosine of {@code x}, for |x| at most pi/4. */
    static double cos(double x) {
        double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
        double low = (C2 + x2 * C4) + x4 * (C6 + x2 * C8);
        double high = (C10 + x2 * C12) + x4 * (C14 + x2 * C16);
        return 1 + x2 * (low + x8 * high);
    }
}
