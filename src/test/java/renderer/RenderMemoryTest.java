package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Geometries;
import geometries.Mesh;
import geometries.Polygon;
import geometries.Sphere;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Limits;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * The heap a render needs is estimated before any work and a render that cannot fit is refused with the figures:
 * image, primitives and the render threads' sample buffers, against what the JVM can give (a fixed figure here, so
 * the test does not depend on the machine).
 */
class RenderMemoryTest {
    private static final long MB = 1_000_000;

    private static Camera.Builder camera(Scene scene, int width, int height) {
        return Camera.getBuilder()
                .setLocation(new Point(0, 0, 10))
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpDistance(10)
                .setVpSize(8, 8)
                .setResolution(width, height)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    private static String refusal(Camera camera, int width, int height, long heap) {
        IllegalStateException e =
                assertThrows(IllegalStateException.class, () -> RenderMemory.check(camera, width, height, () -> heap));
        return e.getMessage();
    }

    @Test
    void theImageIsCountedAt28BytesPerPixel() {
        Camera camera = camera(new Scene("empty"), 1000, 1000).setThreads(1).build();
        RenderMemory.check(camera, 1000, 1000, () -> 29 * MB); // 28 MB and the thread's scratch fit
        String message = refusal(camera, 1000, 1000, 20 * MB);
        assertTrue(message.startsWith("the render needs about 29 MB of memory (the 1000 x 1000 image 28 MB"), message);
        assertTrue(
                message.endsWith("but this JVM can give 20 MB; render it smaller, with fewer samples or threads, or"
                        + " give Java more memory (-Xmx)"),
                message);
        // A region needs only its own pixels.
        RenderMemory.check(camera, 100, 100, () -> 20 * MB);
    }

    @Test
    void everyThreadNeedsItsSampleBuffers() {
        Scene scene = new Scene("soft");
        scene.lights.add(new PointLight(new Color(1, 1, 1), new Point(0, 0, 5))
                .setRadius(1)
                .setNumSamples(Limits.MAX_SAMPLES));
        Camera camera = camera(scene, 64, 64)
                .setThreads(2)
                .setSamplingConfig(
                        new SamplingConfig(Limits.MAX_SAMPLES, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .build();
        // Per thread: 16 bytes per camera sample and per shadow sample, 2^20 of each: 34 MB; two threads.
        String message = refusal(camera, 64, 64, 50 * MB);
        assertTrue(message.contains(", 2 render threads 68 MB)"), message);
        RenderMemory.check(camera, 64, 64, () -> 80 * MB);
        // A 4 x 3 image is one tile: one thread, whatever was asked.
        assertEquals(1, RenderMemory.workers(camera, 4, 3));
        RenderMemory.check(camera, 4, 3, () -> 40 * MB);
    }

    @Test
    void threadsNeverExceedTheMachinesLimit() {
        Camera camera =
                camera(new Scene("empty"), 4096, 4096).setThreads(100_000).build();
        assertEquals(Limits.maxThreads(), RenderMemory.workers(camera, 4096, 4096));
        assertTrue(Limits.maxThreads() <= Limits.MAX_THREADS);
        assertTrue(Limits.maxThreads() >= Limits.THREADS_PER_PROCESSOR);
    }

    @Test
    void primitivesAreTheAcceleratorsTriangles() {
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
        Mesh mesh = new Mesh(v, new int[] {0, 1, 2, 1, 3, 2});
        Polygon pentagon = new Polygon(
                new Point(0, 0, 0), new Point(2, 0, 0), new Point(3, 1, 0), new Point(1, 2, 0), new Point(-1, 1, 0));
        Geometries root = new Geometries(
                new Sphere(Point.ZERO, 1), new Geometries(mesh, new Geometries(pentagon, new Sphere(Point.ZERO, 2))));
        assertEquals(1 + 2 + 3 + 1, RenderMemory.primitives(root));

        Scene scene = new Scene("meshes").setGeometries(root);
        String message = refusal(camera(scene, 10, 10).setThreads(1).build(), 10, 10, 0);
        assertTrue(message.contains(", 7 primitives 1 MB,"), message);
    }

    @Test
    void theCameraRefusesBeforeAnyWork() {
        // 2^28 pixels need 7.5 GB: refused at once wherever the heap is smaller, before a pixel is traced.
        Camera camera =
                camera(new Scene("huge"), 1 << 14, 1 << 14).setThreads(1).build();
        if (Runtime.getRuntime().maxMemory() >= 8_000_000_000L) return; // a heap that large would render it
        long start = System.nanoTime();
        IllegalStateException e = assertThrows(IllegalStateException.class, camera::renderImage);
        assertTrue(e.getMessage().contains("the 16384 x 16384 image 7.5 GB"), e.getMessage());
        assertTrue((System.nanoTime() - start) * 1e-9 < 5, "refused before rendering");
        assertEquals(null, camera.getImage());
    }

    @Test
    void bytesAreWrittenInMegabytesOrGigabytes() {
        assertEquals("1 MB", RenderMemory.bytes(1));
        assertEquals("512 MB", RenderMemory.bytes(512 * MB));
        assertEquals("7.5 GB", RenderMemory.bytes(7_516_192_768L));
    }
}
