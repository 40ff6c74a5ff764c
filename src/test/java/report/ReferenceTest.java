package report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import primitives.Color;
import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;

/** An experiment's reference: the mean of two renders with different seeds, and half their difference as its error. */
class ReferenceTest {
    private static final int W = 16, H = 12;

    @Test
    void isTheMeanOfTwoSeedsWithHalfTheirDifferenceAsItsError() {
        Experiment experiment = new AntiAliasingExperiment();
        Reference reference = Reference.render(experiment, W, H);

        ImageWriter first = experiment.reference(W, H).renderImage().getImage();
        Camera other = experiment.reference(W, H);
        Scene scene = other.getRayTracer().getScene();
        scene.setSeed(~scene.getSeed());
        ImageWriter second = other.renderImage().getImage();
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                Color a = first.getPixel(x, y),
                        b = second.getPixel(x, y),
                        m = reference.image().getPixel(x, y);
                assertEquals((a.getR() + b.getR()) / 2, m.getR(), 0.0);
                assertEquals((a.getG() + b.getG()) / 2, m.getG(), 0.0);
                assertEquals((a.getB() + b.getB()) / 2, m.getB(), 0.0);
            }
        }
        double difference = ImageError.between(first, second).rmse();
        assertTrue(difference > 0, "another seed, other jittered samples");
        assertEquals(difference / 2, reference.ownError(), 0.0);
        assertTrue(reference.seconds() > 0);
    }

    @Test
    void itsOwnErrorIsTakenOutInSquares() {
        assertEquals(4, Reference.without(5, 3), 1e-12);
        assertEquals(0, Reference.without(0.5, 0.6), "a measured error below the reference's own is all of it");
    }
}
