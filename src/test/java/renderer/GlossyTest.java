package renderer;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Plane;
import geometries.Sphere;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/** Glossy reflection and frosted refraction: roughness spreads secondary rays over a cone. */
class GlossyTest {
    private static final int N = 80;

    /** A mirror floor seen at an angle, reflecting a small bright sphere. */
    private static ImageWriter mirror(Material floor, String name) {
        Scene scene = new Scene("glossy").setBackground(new Color(0, 0, 0));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(floor),
                new Sphere(new Point(0, 60, 12), 6).setEmission(new Color(255, 255, 255)));
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -60, 12))
                .setDirection(new Point(0, 30, 0), Vector.AXIS_Z)
                .setVpDistance(100)
                .setVpSize(40, 40)
                .setResolution(N, N)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build()
                .renderImage();
        camera.writeToImage("tests/glossy-" + name);
        return camera.getImage();
    }

    /** Pixels of the lower half (the floor) brighter than 10: the size of the reflected highlight. */
    private static int highlight(ImageWriter image) {
        int count = 0;
        for (int y = N / 2 + 2; y < N; y++) {
            for (int x = 0; x < N; x++) if (FeatureScenes.brightness(image, x, y) > 10) count++;
        }
        return count;
    }

    @Test
    void zeroRoughnessIsExactlyTheMirror() {
        ImageWriter mirror = mirror(new Material().setKr(0.9), "mirror");
        ImageWriter zero = mirror(new Material().setKr(0.9).setRoughness(0), "rough0");
        assertNull(FeatureScenes.firstDifference(mirror, zero));
    }

    @Test
    void moreRoughnessWidensTheReflectedHighlight() {
        int sharp = highlight(mirror(new Material().setKr(0.9), "sharp"));
        int slight = highlight(mirror(new Material().setKr(0.9).setRoughness(0.05), "rough005"));
        int strong = highlight(mirror(new Material().setKr(0.9).setRoughness(0.2), "rough02"));
        assertTrue(sharp > 10, "the mirror shows the sphere: " + sharp);
        assertTrue(slight > sharp, slight + " > " + sharp);
        assertTrue(strong > slight * 3 / 2, strong + " > 1.5 x " + slight);
    }

    @Test
    void frostedGlassBlursWhatIsBehindIt() {
        Scene clear = new Scene("frost");
        Scene frosted = new Scene("frost");
        for (Scene s : new Scene[] {clear, frosted}) {
            s.geometries.add(new Sphere(new Point(0, 0, -200), 10).setEmission(new Color(255, 255, 255)));
        }
        clear.geometries.add(new geometries.Polygon(
                        new Point(-50, -50, -100),
                        new Point(50, -50, -100),
                        new Point(50, 50, -100),
                        new Point(-50, 50, -100))
                .setMaterial(new Material().setKt(1)));
        frosted.geometries.add(new geometries.Polygon(
                        new Point(-50, -50, -100),
                        new Point(50, -50, -100),
                        new Point(50, 50, -100),
                        new Point(-50, 50, -100))
                .setMaterial(new Material().setKt(1).setRoughness(0.1)));
        int sharp = litPixels(clear), blurred = litPixels(frosted);
        assertTrue(blurred > sharp * 2, "frosted " + blurred + " vs clear " + sharp);
    }

    private static int litPixels(Scene scene) {
        ImageWriter image = Camera.getBuilder()
                .setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                .setVpDistance(100)
                .setVpSize(40, 40)
                .setResolution(N, N)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build()
                .renderImage()
                .getImage();
        int count = 0;
        for (int y = 0; y < N; y++) for (int x = 0; x < N; x++) if (FeatureScenes.brightness(image, x, y) > 5) count++;
        return count;
    }

    @Test
    void roughnessOutsideItsRangeIsRejected() {
        for (double bad : new double[] {-0.1, 1.5, Double.NaN}) {
            IllegalArgumentException e =
                    assertThrows(IllegalArgumentException.class, () -> new Material().setRoughness(bad));
            assertTrue(e.getMessage().contains("roughness"), e.getMessage());
        }
    }
}
