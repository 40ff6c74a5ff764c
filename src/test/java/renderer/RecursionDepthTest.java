package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Plane;
import java.util.concurrent.atomic.AtomicReference;
import lighting.PointLight;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * Recursion is bounded ({@link RenderSettings#MAX_LEVEL}) and the bound cannot overflow a stack: two mirrors
 * facing each other (one of them rough) with a clear pane between them render at the deepest level, through
 * reflection, glossy and refraction frames, even when the caller has a small stack, since the render threads get
 * stacks of their own. Deeper is refused.
 */
class RecursionDepthTest {
    /** A caller stack far below the JVM's default (512 KB to 1 MB): the render must not depend on it. */
    private static final long SMALL_STACK = 128 << 10;

    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void facingMirrorsRenderAtTheDeepestLevelFromASmallStack(int threads) throws InterruptedException {
        Scene scene = new Scene("mirrors");
        // Every path is one ray deep down (no material both reflects and transmits, and only the first rough bounce
        // splits), so the render is quick however deep it goes.
        scene.geometries.add(
                new Plane(new Point(0, 0, -1), Vector.AXIS_Z).setMaterial(new Material().setKr(1)),
                new Plane(new Point(0, 0, 1), Vector.AXIS_Z)
                        .setMaterial(new Material().setKr(1).setRoughness(0.01)),
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKt(1)));
        scene.lights.add(new PointLight(new Color(100, 100, 100), new Point(0.2, 0.2, 0.5)));
        Camera camera = Camera.getBuilder()
                .setLocation(Point.ZERO)
                .setDirection(new Vector(0.001, 0, 1), Vector.AXIS_X)
                .setVpDistance(1)
                .setVpSize(1, 1)
                .setResolution(8, 8)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .setRenderSettings(RenderSettings.DEFAULT.withRecursion(RenderSettings.MAX_LEVEL, 0))
                .setThreads(threads)
                .build();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread caller = new Thread(
                null,
                () -> {
                    try {
                        camera.renderImage();
                    } catch (Throwable e) {
                        failure.set(e);
                    }
                },
                "small-stack",
                SMALL_STACK);
        caller.start();
        caller.join();
        assertNull(failure.get(), () -> "render failed: " + failure.get());
        // The rays really went all the way down: every pixel bounced between the mirrors to the last level.
        RayCounters rays = camera.getLastStatistics().rays();
        String counts = "reflection " + rays.reflection + ", refraction " + rays.refraction + ", glossy " + rays.glossy;
        assertTrue(rays.reflection + rays.refraction >= 64L * (RenderSettings.MAX_LEVEL - 1), counts);
        assertTrue(rays.glossy > 0 && rays.refraction > 0, counts);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 8; x++) {
                Color c = camera.getImage().getPixel(x, y);
                assertTrue(Double.isFinite(c.getR() + c.getG() + c.getB()), "pixel " + x + ", " + y);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {0, RenderSettings.MAX_LEVEL + 1, Integer.MAX_VALUE})
    void deeperThanTheBoundIsRefused(int level) {
        IllegalArgumentException e =
                assertThrows(IllegalArgumentException.class, () -> RenderSettings.DEFAULT.withRecursion(level, 0.001));
        assertEquals("maxLevel must be in [1, 256], but was " + level, e.getMessage());
    }
}
