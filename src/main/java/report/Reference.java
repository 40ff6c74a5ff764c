package report;

import primitives.Color;
import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;

/**
 * An experiment's reference image and its own error. A reference is converged only so far, and its error adds to
 * every error measured against it (in squares: the two are independent). So the reference is rendered twice, with two
 * scene seeds, and is the mean of the two: the two differ by about sqrt 2 times one render's error, and their mean
 * has half that difference as its own error. Taken out of a measured error, what is left estimates the error against
 * the true image, which is what a progressive render predicts. One render of the street's reference, 256 camera rays
 * and 16 shadow rays per lamp, is off by about 0.55 (27 Nov), as much as a 5 s budget's own error.
 *
 * @param image the mean of the two renders
 * @param seconds the wall time of both renders
 * @param ownError the estimated RMSE of {@code image} against the true image
 */
record Reference(ImageWriter image, double seconds, double ownError) {

    /** Renders the experiment's reference at this size twice, with its scene's seed and another one. */
    static Reference render(Experiment experiment, int width, int height) {
        Camera first = experiment.reference(width, height).renderImage();
        Camera second = experiment.reference(width, height);
        Scene scene = second.getRayTracer().getScene();
        scene.setSeed(~scene.getSeed());
        second.renderImage();
        ImageWriter a = first.getImage(), b = second.getImage();
        ImageWriter mean = new ImageWriter("reference", width, height);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                Color p = a.getPixel(x, y), q = b.getPixel(x, y);
                mean.writePixel(x, y, (p.getR() + q.getR()) / 2, (p.getG() + q.getG()) / 2, (p.getB() + q.getB()) / 2);
            }
        }
        double seconds = first.getLastStatistics().wallSeconds()
                + second.getLastStatistics().wallSeconds();
        return new Reference(mean, seconds, ImageError.between(a, b).rmse() / 2);
    }

    /** The error measured against a reference, the reference's own error taken out (0 if it is all of it). */
    static double without(double measured, double referenceError) {
        return Math.sqrt(Math.max(0, measured * measured - referenceError * referenceError));
    }
}
