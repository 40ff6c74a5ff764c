package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import java.util.List;
import java.util.function.Supplier;
import java.util.stream.Stream;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Effect planning fires no ray an effect cannot use, reports what it skipped, and never changes the image. */
class EffectPlanTest {
    private static final int N = 40;

    private static Camera.Builder camera(Scene scene) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -100, 50))
                .setDirection(new Point(0, 0, 10), Vector.AXIS_Z)
                .setVpDistance(100)
                .setVpSize(80, 80)
                .setResolution(N, N)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    private static Scene matte() {
        Scene scene = new Scene("matte").setAmbientLight(new AmbientLight(new Color(20, 20, 20)));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.7)),
                new Sphere(new Point(0, 0, 15), 15)
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(20)));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(30, -30, 80)));
        scene.lights.add(new DirectionalLight(new Color(60, 60, 60), new Vector(-1, 1, -1)));
        return scene;
    }

    @Test
    void aMatteSceneFiresNoReflectionOrRefractionRays() {
        Camera camera = camera(matte()).build().renderImage();
        RenderStatistics stats = camera.getLastStatistics();
        assertEquals(0, stats.rays().reflection);
        assertEquals(0, stats.rays().refraction);
        assertTrue(stats.plan().contains("reflection rays (no material has kR > 0)"), stats.plan());
        assertTrue(stats.plan().contains("refraction rays (no material has kT > 0)"), stats.plan());
    }

    @Test
    void hardLightsFireAtMostOneShadowRayPerLightPerShadingPoint() {
        Camera camera = camera(matte()).build().renderImage();
        RayCounters rays = camera.getLastStatistics().rays();
        // Without secondary rays every shading point is a camera hit: at most 2 lights x camera rays.
        assertTrue(rays.shadow <= 2 * rays.camera, rays.shadow + " shadow rays for " + rays.camera + " camera rays");
        assertTrue(rays.shadow > 0);
    }

    @Test
    void aLightBehindEverySurfaceFiresNoShadowRays() {
        Scene scene = new Scene("behind");
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.7)),
                new Polygon(
                                new Point(-20, -20, 10),
                                new Point(20, -20, 10),
                                new Point(20, 20, 10),
                                new Point(-20, 20, 10))
                        .setMaterial(new Material().setKd(0.5)));
        // Below the floor and the table top: every visible point has the light on its other side.
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(0, 0, -50)));
        Camera camera = camera(scene).build().renderImage();
        assertEquals(0, camera.getLastStatistics().rays().shadow);
        Camera unplanned = camera(scene)
                .setRenderSettings(RenderSettings.DEFAULT.withPlanEffects(false))
                .build()
                .renderImage();
        assertTrue(unplanned.getLastStatistics().rays().shadow > 0, "without planning the rays are fired");
        assertNull(FeatureScenes.firstDifference(camera.getImage(), unplanned.getImage()));
    }

    @Test
    void aSpotLightFiresNoShadowRaysOutsideItsBeam() {
        Scene scene = new Scene("spot");
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.7)));
        scene.geometries.add(new Sphere(new Point(0, 0, 15), 15).setMaterial(new Material().setKd(0.5)));
        // Pointing straight up, away from everything.
        scene.lights.add(new SpotLight(new Color(300, 300, 300), new Point(0, 0, 60), Vector.AXIS_Z));
        assertEquals(0, camera(scene).build().renderImage().getLastStatistics().rays().shadow);
    }

    @Test
    void aLightFiresNoShadowRaysBeyondItsRange() {
        Scene scene = matte();
        scene.lights.clear();
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(0, 0, 200)).setRange(100));
        Camera camera = camera(scene).build().renderImage();
        assertEquals(0, camera.getLastStatistics().rays().shadow, "every visible point is over 100 away");
        scene.lights.clear();
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(0, 0, 200)).setRange(1000));
        assertTrue(camera(scene).build().renderImage().getLastStatistics().rays().shadow > 0);
    }

    @Test
    void aSingleFlatSurfaceNeedsNoShadowTestAtAll() {
        Scene scene = new Scene("floor");
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.7)));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(0, 0, 60))
                .setRadius(5)
                .setNumSamples(16));
        Camera planned = camera(scene).build().renderImage();
        assertEquals(0, planned.getLastStatistics().rays().shadow);
        assertTrue(planned.getLastStatistics().plan().contains("a single flat surface cannot shadow itself"));
        Camera unplanned = camera(scene)
                .setRenderSettings(RenderSettings.DEFAULT.withPlanEffects(false))
                .build()
                .renderImage();
        assertTrue(unplanned.getLastStatistics().rays().shadow > 0);
        assertNull(FeatureScenes.firstDifference(planned.getImage(), unplanned.getImage()));
    }

    /** Scenes and settings across every effect, each rendered with and without planning. */
    static Stream<Arguments> suite() {
        return Stream.of(
                Arguments.of("matte", (Supplier<Scene>) EffectPlanTest::matte, SamplingConfig.NONE),
                Arguments.of("mirror and glass", (Supplier<Scene>) EffectPlanTest::mirrorAndGlass, SamplingConfig.NONE),
                Arguments.of(
                        "soft and glossy",
                        (Supplier<Scene>) EffectPlanTest::softAndGlossy,
                        new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.JITTERED)),
                Arguments.of(
                        "lights off to one side", (Supplier<Scene>) EffectPlanTest::sideLights, SamplingConfig.NONE));
    }

    private static Scene mirrorAndGlass() {
        Scene scene = matte();
        scene.geometries.add(
                new Sphere(new Point(-25, 10, 12), 12)
                        .setMaterial(new Material().setKd(0.1).setKt(0.8).setIndexOfRefraction(1.5)),
                new Polygon(new Point(-60, 40, 0), new Point(60, 40, 0), new Point(60, 40, 60), new Point(-60, 40, 60))
                        .setMaterial(new Material().setKr(0.7)));
        return scene;
    }

    private static Scene softAndGlossy() {
        Scene scene = new Scene("soft").setAmbientLight(new AmbientLight(new Color(20, 20, 20)));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setMaterial(new Material().setKd(0.5).setKr(0.4).setRoughness(0.1)),
                new Sphere(new Point(0, 0, 15), 15)
                        .setMaterial(new Material().setKd(0.3).setKt(0.6).setRoughness(0.05)));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(30, -30, 80))
                .setRadius(6)
                .setNumSamples(9));
        return scene;
    }

    private static Scene sideLights() {
        Scene scene = matte();
        scene.lights.add(new SpotLight(new Color(200, 100, 100), new Point(0, 0, 80), new Vector(0, 0, 1)));
        scene.lights.add(new PointLight(new Color(100, 100, 200), new Point(0, 0, -40)));
        return scene;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("suite")
    void plannedAndUnplannedRendersAreBitIdentical(String name, Supplier<Scene> scene, SamplingConfig aa) {
        Camera planned = camera(scene.get()).setSamplingConfig(aa).build().renderImage();
        Camera unplanned = camera(scene.get())
                .setSamplingConfig(aa)
                .setRenderSettings(RenderSettings.DEFAULT.withPlanEffects(false))
                .build()
                .renderImage();
        assertNull(FeatureScenes.firstDifference(planned.getImage(), unplanned.getImage()), name);
        RayCounters p = planned.getLastStatistics().rays(),
                u = unplanned.getLastStatistics().rays();
        assertTrue(u.total() >= p.total(), "planning never adds rays: " + p.total() + " vs " + u.total());
    }

    @Test
    void statisticsAddUp() {
        int samples = 9;
        Camera camera = camera(softAndGlossy())
                .setSamplingConfig(new SamplingConfig(samples, TargetShape.RECTANGLE, SamplingPattern.GRID))
                .build()
                .renderImage();
        RenderStatistics stats = camera.getLastStatistics();
        RayCounters rays = stats.rays();
        assertEquals((long) N * N * samples, rays.camera, "camera rays = pixels x samples");
        assertEquals((long) N * N, stats.pixels());
        assertEquals(rays.camera + rays.shadow + rays.reflection + rays.refraction, rays.total());
        assertTrue(rays.glossy <= rays.reflection + rays.refraction, "glossy rays are a subset");
        // Shadow rays come in beams of 9 (one light with 9 samples) per shading point.
        assertEquals(0, rays.shadow % 9, "soft shadow rays come 9 per shading point");
        assertTrue(stats.primitiveTests() > 0);
        // One bounded primitive (the sphere; the plane is unbounded): tested directly, no tree is searched.
        assertEquals(0, stats.nodeVisits(), "node visits with a single bounded primitive");
        assertTrue(stats.format().contains("camera"), stats.format());
        List<String> lines = stats.format().lines().toList();
        assertFalse(lines.isEmpty());
    }
}
