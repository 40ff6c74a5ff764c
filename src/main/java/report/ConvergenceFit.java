package report;

/**
 * A straight line through points on log-log axes by least squares: the convergence rate of an error that
 * falls like {@code c x^slope}. Textbook rates: about -0.5 for independent random samples, down to -1 (and better
 * for smooth integrands) for stratified and low-discrepancy samples.
 *
 * @param slope the exponent
 * @param intercept log10 of the constant
 */
public record ConvergenceFit(double slope, double intercept) {

    /**
     * Fits {@code log10 y = intercept + slope log10 x} over the points with positive x and y.
     *
     * @param x the abscissas (sample counts or seconds)
     * @param y the errors, as many as {@code x}
     * @return the fitted line, with NaN slope and intercept when fewer than two usable points or all x equal
     */
    public static ConvergenceFit of(double[] x, double[] y) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        int n = 0;
        for (int i = 0; i < x.length; i++) {
            if (!(x[i] > 0 && y[i] > 0)) continue;
            double lx = Math.log10(x[i]), ly = Math.log10(y[i]);
            sx += lx;
            sy += ly;
            sxx += lx * lx;
            sxy += lx * ly;
            n++;
        }
        if (n < 2) return new ConvergenceFit(Double.NaN, Double.NaN);
        double denominator = n * sxx - sx * sx;
        if (denominator == 0) return new ConvergenceFit(Double.NaN, Double.NaN);
        double slope = (n * sxy - sx * sy) / denominator;
        return new ConvergenceFit(slope, (sy - slope * sx) / n);
    }

    /**
     * How many times more of x (samples or seconds) halve the error: {@code 2^(-1/slope)}; infinite when the
     * error does not fall.
     *
     * @return the factor by which x must grow to halve the error, or {@link Double#POSITIVE_INFINITY}
     */
    public double factorToHalveError() {
        return slope < 0 ? Math.pow(2, -1 / slope) : Double.POSITIVE_INFINITY;
    }
}
