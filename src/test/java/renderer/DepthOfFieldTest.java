package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Sphere;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Depth of field: what lies on the focal plane stays sharp, what lies far from it blurs. */
class DepthOfFieldTest {
    private static final int N = 100;

    /** A sphere in focus at distance 100 on the left and one far behind (distance 400) on the right. */
    private static Camera camera() {
        Scene scene = new Scene("dof");
        scene.geometries.add(
                new Sphere(new Point(-20, 0, -100), 12).setEmission(new Color(255, 255, 255)),
                new Sphere(new Point(80, 0, -400), 48).setEmission(new Color(255, 255, 255)));
        return Camera.getBuilder()
                .setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                .setVpDistance(100)
                .setVpSize(80, 80)
                .setResolution(N, N)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
    }

    /** Pixels of the middle row in columns [from, to) that are neither black nor fully white. */
    private static int blurredPixels(ImageWriter image, int from, int to) {
        int count = 0;
        for (int x = from; x < to; x++) {
            double b = FeatureScenes.brightness(image, x, N / 2);
            if (b > 2 && b < 253) count++;
        }
        return count;
    }

    @Test
    void theFocusedSphereStaysSharpWhileTheFarOneBlurs() {
        Camera camera = camera().setDepthOfField(100, 3)
                .setApertureSampling(new SamplingConfig(64, TargetShape.CIRCLE, SamplingPattern.JITTERED));
        ImageWriter image = camera.renderImage().getImage();
        camera.writeToImage("tests/dof");
        // The near sphere spans columns 10..40 and the far one 60..90 of the middle row.
        int near = blurredPixels(image, 0, N / 2), far = blurredPixels(image, N / 2, N);
        assertTrue(near <= 4, "in-focus edge pixels: " + near);
        assertTrue(far >= 10, "out-of-focus edge pixels: " + far);
        assertEquals(64L * N * N, camera.getLastStatistics().rays().depthOfField);
    }

    @Test
    void aPinholeAndAZeroApertureGiveTheSameImage() {
        ImageWriter pinhole = camera().renderImage().getImage();
        ImageWriter zero = camera().setDepthOfField(100, 0).renderImage().getImage();
        assertNull(FeatureScenes.firstDifference(pinhole, zero));
    }

    @Test
    void badLensSettingsAreRejected() {
        Camera camera = camera();
        assertTrue(assertThrows(IllegalArgumentException.class, () -> camera.setDepthOfField(100, -1))
                .getMessage()
                .contains("aperture"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> camera.setDepthOfField(0, 1))
                .getMessage()
                .contains("focal distance"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> camera.setDepthOfField(-5, 1))
                .getMessage()
                .contains("-5"));
    }
}
