package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Sphere;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import primitives.Color;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Anti-aliasing by supersampling: silhouettes get intermediate colours, flat regions do not change. */
class AntiAliasingTest {
    private static final int N = 64;
    private static final Color SPHERE = new Color(200, 120, 40);
    private static final Color BACKGROUND = new Color(10, 20, 90);

    private static Camera camera() {
        Scene scene = new Scene("aa").setBackground(BACKGROUND);
        scene.geometries.add(new Sphere(new Point(0, 0, -100), 30).setEmission(SPHERE));
        return Camera.getBuilder()
                .setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                .setVpDistance(100)
                .setVpSize(80, 80)
                .setResolution(N, N)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
    }

    private static Set<Color> colours(ImageWriter image) {
        Set<Color> set = new HashSet<>();
        for (int y = 0; y < N; y++) for (int x = 0; x < N; x++) set.add(image.getPixel(x, y));
        return set;
    }

    @Test
    void withoutAntiAliasingOnlyThePureColoursAppear() {
        ImageWriter image = camera().renderImage().getImage();
        assertEquals(Set.of(SPHERE, BACKGROUND), colours(image));
    }

    @ParameterizedTest
    @EnumSource(SamplingPattern.class)
    void withAntiAliasingTheSilhouetteTakesIntermediateColoursAndOnlyThere(SamplingPattern pattern) {
        ImageWriter plain = camera().renderImage().getImage();
        Camera camera = camera().setSamplingConfig(new SamplingConfig(16, TargetShape.RECTANGLE, pattern));
        ImageWriter smooth = camera.renderImage().getImage();
        camera.writeToImage("tests/aa-" + pattern);
        int intermediate = 0;
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                Color c = smooth.getPixel(x, y);
                if (c.equals(plain.getPixel(x, y))) continue;
                // A changed pixel must lie on an edge of the plain image.
                assertTrue(onEdge(plain, x, y), "pixel " + x + "," + y + " changed away from any edge");
                double t = (c.getR() - BACKGROUND.getR()) / (SPHERE.getR() - BACKGROUND.getR());
                assertTrue(t > 0 && t < 1, "pixel " + x + "," + y + " is a blend, t = " + t);
                intermediate++;
            }
        }
        // The silhouette of a circle of radius 24 pixels crosses about 2 * pi * 24 = 150 pixels.
        assertTrue(intermediate > 100, "only " + intermediate + " blended silhouette pixels");
        assertEquals(16L * N * N, camera.getLastStatistics().rays().camera, "16 camera rays per pixel");
    }

    /** Whether a 3 x 3 neighbourhood of the pixel holds more than one colour. */
    static boolean onEdge(ImageWriter image, int x, int y) {
        Color c = image.getPixel(x, y);
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= image.getNx() || ny >= image.getNy()) continue;
                if (!image.getPixel(nx, ny).equals(c)) return true;
            }
        }
        return false;
    }

    @Test
    void adaptiveAntiAliasingStaysCloseToTheFixedGridWithFewerRays() {
        Camera fixed = camera().setSamplingConfig(new SamplingConfig(81, TargetShape.RECTANGLE, SamplingPattern.GRID));
        ImageWriter reference = fixed.renderImage().getImage();
        long fixedRays = fixed.getLastStatistics().rays().camera;
        Camera adaptive = camera().setSamplingConfig(
                        new SamplingConfig(81, TargetShape.RECTANGLE, SamplingPattern.GRID).adaptive(8));
        ImageWriter image = adaptive.renderImage().getImage();
        adaptive.writeToImage("tests/aa-adaptive");
        long adaptiveRays = adaptive.getLastStatistics().rays().camera;
        assertTrue(adaptiveRays * 3 < fixedRays, adaptiveRays + " adaptive rays vs " + fixedRays + " fixed");
        assertEquals(fixedRays - adaptiveRays, adaptive.getLastStatistics().rays().samplesSaved);
        // Stated tolerance: RMS difference below 2 and no pixel off by more than 40 (of 255).
        double rms = FeatureScenes.rmsDifference(reference, image), max = FeatureScenes.maxDifference(reference, image);
        assertTrue(rms < 2 && max < 40, "rms " + rms + ", max " + max);
        // Flat regions take exactly the corner colour: the interior and the background match the plain render.
        ImageWriter plain = camera().renderImage().getImage();
        assertEquals(plain.getPixel(N / 2, N / 2), image.getPixel(N / 2, N / 2));
        assertEquals(plain.getPixel(1, 1), image.getPixel(1, 1));
    }
}
