package report;

import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;

/**
 * The own error of an experiment's reference. A reference is converged only so far, and its error adds to every
 * error measured against it (in squares: the two are independent). A second reference, rendered the same way with
 * another scene seed, differs from the first by about sqrt 2 times that error. Taken out of a measured error, what is
 * left estimates the error against the true image, which is what a progressive render predicts: the street's
 * reference, at 256 camera rays and 16 shadow rays per lamp, is off by about 0.55, as much as a 5 s budget's own error.
 */
final class ReferenceError {
    private ReferenceError() {}

    /**
     * The own RMSE of {@code reference}, the experiment's reference at this size: the experiment's reference rendered
     * again with another seed, its RMSE against {@code reference}, over sqrt 2.
     */
    static double estimate(Experiment experiment, int width, int height, ImageWriter reference) {
        Camera second = experiment.reference(width, height);
        Scene scene = second.getRayTracer().getScene();
        scene.setSeed(~scene.getSeed());
        ImageWriter other = second.renderImage().getImage();
        return ImageError.between(other, reference).rmse() / Math.sqrt(2);
    }

    /** The error measured against the reference, the reference's own error taken out (0 if it is all of it). */
    static double without(double measured, double referenceError) {
        return Math.sqrt(Math.max(0, measured * measured - referenceError * referenceError));
    }
}
