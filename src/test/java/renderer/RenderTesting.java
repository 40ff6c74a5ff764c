package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Helpers of the render tests: a top-down camera over the floor z = 0, the floor point a pixel sees (computed
 * analytically from the pixel's ray, independently of the renderer), rendering with an image written to
 * {@code images/test-<name>.png}, and colour assertions.
 */
final class RenderTesting {
    /** Camera height above the floor. */
    static final double HEIGHT = 10;

    private RenderTesting() {}

    /** A camera at (0,0,10) looking down (-z) with +y up: a 20 x 20 view of the floor at distance 10. */
    static Camera.Builder topDown(Scene scene, int n) {
        return Camera.getBuilder()
                .setLocation(new Point(0, 0, HEIGHT))
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpDistance(HEIGHT)
                .setVpSize(20, 20)
                .setResolution(n, n)
                .setThreads(2)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    /** Where the ray of pixel (j, i) meets the plane z = 0. */
    static Point floorPoint(Camera camera, int j, int i) {
        Ray ray = camera.constructRay(camera.getNx(), camera.getNy(), j, i);
        double t = -ray.getHead().z / ray.getDirection().z;
        return ray.getPoint(t);
    }

    /** Renders and writes {@code images/test-<name>.png}; returns the camera for pixel reads. */
    static Camera render(Camera camera, String name) {
        camera.renderImage();
        Path file = camera.writeToImage("test-" + name);
        assertTrue(Files.isRegularFile(file), "image written: " + file);
        return camera;
    }

    static void assertColor(Color expected, Color actual, double tolerance, String message) {
        assertEquals(expected.getR(), actual.getR(), tolerance, message + " red: " + actual + " vs " + expected);
        assertEquals(expected.getG(), actual.getG(), tolerance, message + " green: " + actual + " vs " + expected);
        assertEquals(expected.getB(), actual.getB(), tolerance, message + " blue: " + actual + " vs " + expected);
    }

    /** Mean of the three channels. */
    static double brightness(Color c) {
        return (c.getR() + c.getG() + c.getB()) / 3;
    }

    /** Distance from {@code c} to the segment from {@code a} to {@code b}. */
    static double distanceToSegment(Point c, Point a, Point b) {
        double abx = b.x - a.x, aby = b.y - a.y, abz = b.z - a.z;
        double s = ((c.x - a.x) * abx + (c.y - a.y) * aby + (c.z - a.z) * abz) / (abx * abx + aby * aby + abz * abz);
        s = Math.max(0, Math.min(1, s));
        return c.distance(new Point(a.x + s * abx, a.y + s * aby, a.z + s * abz));
    }
}
