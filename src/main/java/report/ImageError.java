package report;

import java.util.Arrays;
import primitives.Color;
import renderer.ImageWriter;

/**
 * The error of an image against a reference as the viewer sees it: channels clamped to the displayable 0..255,
 * per-pixel error the root mean square over the three channels, summarised as the RMSE over all pixels and the
 * 99th percentile of the per-pixel error (the worst 1% are the artefacts one notices).
 *
 * @param rmse root mean square error over pixels and channels (0..255 scale)
 * @param p99 99th percentile of the per-pixel error (0..255 scale)
 */
public record ImageError(double rmse, double p99) {

    /**
     * The error of {@code image} against {@code reference} (same size).
     *
     * @param image the image measured
     * @param reference the converged reference, of the same size
     * @return the RMSE and 99th-percentile error on the 0..255 scale
     * @throws IllegalArgumentException if the sizes differ
     */
    public static ImageError between(ImageWriter image, ImageWriter reference) {
        if (image.getNx() != reference.getNx() || image.getNy() != reference.getNy()) {
            throw new IllegalArgumentException("image " + image.getNx() + " x " + image.getNy() + " and reference "
                    + reference.getNx() + " x " + reference.getNy() + " differ in size");
        }
        int n = image.getNx() * image.getNy();
        double[] perPixel = new double[n];
        double sum = 0;
        for (int y = 0, i = 0; y < image.getNy(); y++) {
            for (int x = 0; x < image.getNx(); x++, i++) {
                Color a = image.getPixel(x, y), b = reference.getPixel(x, y);
                double dr = clamp(a.getR()) - clamp(b.getR());
                double dg = clamp(a.getG()) - clamp(b.getG());
                double db = clamp(a.getB()) - clamp(b.getB());
                double squared = (dr * dr + dg * dg + db * db) / 3;
                sum += squared;
                perPixel[i] = Math.sqrt(squared);
            }
        }
        Arrays.sort(perPixel);
        int rank = (int) Math.ceil(0.99 * n) - 1;
        return new ImageError(Math.sqrt(sum / n), perPixel[Math.max(0, rank)]);
    }

    private static double clamp(double v) {
        return v < 0 ? 0 : v > 255 ? 255 : v;
    }
}
