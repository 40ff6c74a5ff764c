package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Plane;
import geometries.Sphere;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import lighting.AmbientLight;
import lighting.PointLight;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * A render can be cancelled from Java: by interrupting the rendering thread, or by {@link Camera#cancel()} from
 * another thread. It stops within a tile row (well within a second here, where the whole render takes far
 * longer), throws a {@link CancellationException}, produces no image, leaves the caller's interrupt status set,
 * and the camera renders normally afterwards.
 */
class RenderCancellationTest {
    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void interruptingTheCallerCancelsTheRender(int threads) throws Exception {
        Camera camera = heavyCamera(threads);
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        AtomicBoolean stillInterrupted = new AtomicBoolean();
        Thread renderer = new Thread(() -> {
            try {
                camera.renderImage();
            } catch (Throwable e) {
                thrown.set(e);
                stillInterrupted.set(Thread.currentThread().isInterrupted());
            }
        });
        renderer.start();
        Thread.sleep(300);
        long asked = System.nanoTime();
        renderer.interrupt();
        renderer.join(10_000);
        double seconds = (System.nanoTime() - asked) * 1e-9;
        assertTrue(!renderer.isAlive(), "the render stopped");
        assertInstanceOf(CancellationException.class, thrown.get());
        assertTrue(stillInterrupted.get(), "the caller keeps its interrupt status");
        assertTrue(seconds < 5, "stopped " + seconds + " s after the interrupt");
        assertEquals(null, camera.getImage(), "no image");
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void cancelFromAnotherThreadStopsTheRenderAndTheCameraStillWorks(int threads) throws Exception {
        Camera camera = heavyCamera(threads);
        Thread canceller = new Thread(() -> {
            try {
                Thread.sleep(300);
            } catch (InterruptedException e) {
                return;
            }
            camera.cancel();
        });
        canceller.start();
        long start = System.nanoTime();
        CancellationException e =
                org.junit.jupiter.api.Assertions.assertThrows(CancellationException.class, camera::renderImage);
        assertTrue((System.nanoTime() - start) * 1e-9 < 5, "stopped soon after cancel()");
        assertTrue(e.getMessage().contains("cancelled"), e.getMessage());
        canceller.join();

        // A later render is unaffected, and equals a fresh camera's.
        Camera small = smallCamera(camera);
        small.renderImage();
        Camera fresh = smallCamera(heavyCamera(threads));
        fresh.renderImage();
        for (int y = 0; y < 30; y++) {
            for (int x = 0; x < 40; x++)
                assertEquals(fresh.getImage().getPixel(x, y), small.getImage().getPixel(x, y));
        }
    }

    private static Camera smallCamera(Camera like) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -8, 3))
                .setDirection(new Point(0, 0, 1), Vector.AXIS_Z)
                .setVpDistance(6)
                .setVpSize(4, 3)
                .setResolution(40, 30)
                .setRayTracer(like.getRayTracer())
                .setThreads(like.getThreads())
                .build();
    }

    /** A render of many seconds: 400 x 300 pixels, 256 camera rays each, a soft light of 64 shadow rays. */
    private static Camera heavyCamera(int threads) {
        Scene scene = new Scene("cancel").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setMaterial(new Material().setKd(0.6).setKr(0.3)),
                new Sphere(new Point(0, 0, 1), 1)
                        .setMaterial(new Material().setKd(0.5).setKs(0.5)));
        scene.lights.add(new PointLight(new Color(300, 280, 250), new Point(3, -4, 6))
                .setRadius(0.5)
                .setNumSamples(64));
        return Camera.getBuilder()
                .setLocation(new Point(0, -8, 3))
                .setDirection(new Point(0, 0, 1), Vector.AXIS_Z)
                .setVpDistance(6)
                .setVpSize(4, 3)
                .setResolution(400, 300)
                .setSamplingConfig(new SamplingConfig(256, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .setThreads(threads)
                .build();
    }
}
