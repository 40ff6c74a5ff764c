package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Meshes;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import java.util.function.Predicate;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * The per-render BVH switch changes speed only: a scene of meshes, spheres, a polygon and a plane, with soft
 * shadows, glass and a mirror, renders to the same pixels bit for bit with the BVH on two threads and by brute
 * force on one.
 */
class BvhRenderEqualityTest {
    @Test
    void bvhAndBruteForceRenderIdenticalImages() {
        ImageWriter withBvh = render(true, 2);
        ImageWriter bruteForce = render(false, 1);
        assertIdentical(bruteForce, withBvh, "");
        int lit = count(withBvh, c -> c.getR() + c.getG() + c.getB() > 0);
        assertTrue(lit > withBvh.getNx() * withBvh.getNy() / 2, "the image shows the scene, not just black");
    }

    /** Asserts the two images' pixels equal bit for bit. */
    private static void assertIdentical(ImageWriter expected, ImageWriter actual, String context) {
        for (int y = 0; y < expected.getNy(); y++) {
            for (int x = 0; x < expected.getNx(); x++) {
                Color e = expected.getPixel(x, y), a = actual.getPixel(x, y);
                String where = "pixel (" + x + ", " + y + ")" + context;
                assertEquals(Double.doubleToLongBits(e.getR()), Double.doubleToLongBits(a.getR()), where);
                assertEquals(Double.doubleToLongBits(e.getG()), Double.doubleToLongBits(a.getG()), where);
                assertEquals(Double.doubleToLongBits(e.getB()), Double.doubleToLongBits(a.getB()), where);
            }
        }
    }

    private static int count(ImageWriter image, Predicate<Color> which) {
        int n = 0;
        for (int y = 0; y < image.getNy(); y++) {
            for (int x = 0; x < image.getNx(); x++) if (which.test(image.getPixel(x, y))) n++;
        }
        return n;
    }

    /** A pinhole camera of this test's scenes, for the BVH on or off. */
    private static Camera camera(
            Scene scene, Point from, Point to, double width, double height, int nX, int nY, boolean useBvh) {
        return Camera.getBuilder()
                .setLocation(from)
                .setDirection(to, Vector.AXIS_Z)
                .setVpDistance(1)
                .setVpSize(width, height)
                .setResolution(nX, nY)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .setBvh(useBvh)
                .build();
    }

    /**
     * Opaque spheres over a plane under a soft light: by brute force their shadow rays are tested in packets (each
     * sphere against a whole beam), through the tree one by one; the images are the same bit for bit, for fixed
     * samples and for progressive ones, whose batches put several samples' beams in one packet.
     */
    @Test
    void shadowPacketsRenderAsSingleShadowRaysDo() {
        for (ProgressiveSettings progressive : new ProgressiveSettings[] {null, ProgressiveSettings.targetError(3)}) {
            ImageWriter tree = renderSpheres(true, progressive), packets = renderSpheres(false, progressive);
            assertIdentical(tree, packets, ", progressive " + progressive);
            int penumbra = count(tree, c -> c.getR() > 40 && c.getR() < 120);
            assertTrue(penumbra > 20, "the image has soft shadows to compare: " + penumbra + " mid-tone pixels");
        }
    }

    private static ImageWriter renderSpheres(boolean useBvh, ProgressiveSettings progressive) {
        Scene scene = new Scene("shadow-packets").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.05));
        scene.geometries.add(new Plane(new Point(0, 0, 0), Vector.AXIS_Z).setMaterial(new Material().setKd(0.6)));
        for (int i = 0; i < 5; i++) {
            scene.geometries.add(new Sphere(new Point(-1.2 + 0.6 * i, 0.3 * (i % 2), 0.6 + 0.15 * i), 0.25)
                    .setMaterial(new Material().setKd(0.5)));
        }
        scene.lights.add(new PointLight(new Color(255, 255, 255), new Point(0.5, -0.5, 3))
                .setRadius(0.4)
                .setNumSamples(2));
        Camera camera = camera(scene, new Point(0, -4, 3), new Point(0, 0, 0.3), 1.2, 0.9, 40, 30, useBvh)
                .setThreads(useBvh ? 2 : 1);
        if (progressive != null) camera.setProgressive(progressive);
        camera.renderImage();
        return camera.getImage();
    }

    private static ImageWriter render(boolean useBvh, int threads) {
        Scene scene = new Scene("bvh-equality")
                .setBackground(new Color(10, 10, 20))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Plane(new Point(0, 0, -0.3), Vector.AXIS_Z)
                        .setEmission(new Color(30, 30, 30))
                        .setMaterial(new Material().setKd(0.5).setKr(0.2)),
                Meshes.heightfield(16)
                        .setEmission(new Color(20, 60, 20))
                        .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(30)),
                Meshes.icosphere(3)
                        .setEmission(new Color(20, 20, 60))
                        .setMaterial(new Material()
                                .setKd(0.2)
                                .setKs(0.5)
                                .setShininess(100)
                                .setKt(0.5)),
                new Sphere(new Point(1.2, 0.8, 0.5), 0.4)
                        .setEmission(new Color(60, 10, 10))
                        .setMaterial(new Material().setKd(0.3).setKr(0.6)),
                new Polygon(
                                new Point(-1.5, 1, -0.3),
                                new Point(-0.5, 1.5, -0.3),
                                new Point(-0.5, 1.5, 1),
                                new Point(-1.5, 1, 1))
                        .setEmission(new Color(40, 40, 10))
                        .setMaterial(new Material().setKd(0.5)));
        scene.lights.add(new PointLight(new Color(300, 280, 250), new Point(-2, -2, 4))
                .setRadius(0.3)
                .setNumSamples(4));
        scene.lights.add(new DirectionalLight(new Color(60, 60, 80), new Vector(0.3, 1, -1)));
        Camera camera = camera(scene, new Point(0, -4, 2.5), new Point(0, 0, 0), 1.2, 0.75, 48, 30, useBvh)
                .setThreads(threads);
        camera.renderImage();
        return camera.getImage();
    }
}
