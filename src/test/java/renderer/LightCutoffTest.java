package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Plane;
import geometries.Sphere;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.stream.Stream;
import lighting.AmbientLight;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;
import sceneio.SceneLoader;
import sceneio.model.SceneDocument;

/**
 * The light cut-off ({@link RenderSettings#lightCutoff}) keeps its promise on every scene file of the suite and on
 * a scene built to trigger it: no linear channel of any pixel moves by as much as the cut-off (half a display step
 * by default), so no 8-bit channel moves by more than one step; the pixels that do change are counted and printed.
 * With a cut-off of 0 nothing is set aside.
 */
class LightCutoffTest {
    private static final double CUTOFF = RenderSettings.DEFAULT.lightCutoff();

    /** The scene files of scenes/, small. */
    static Stream<String> sceneFiles() {
        return Stream.of("street", "showcase", "glass-and-mirror", "soft-shadows", "aa-edges", "textured-model");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sceneFiles")
    void theCutoffMovesNoChannelByHalfAStepOnEverySceneFile(String name) throws Exception {
        Path file = Path.of("scenes", name + ".json");
        SceneDocument d = SceneLoader.read(file);
        d = d.withRender(d.render().withSize(96, 60).withThreads(2));
        Camera exact = SceneLoader.build(d, file).camera();
        exact.setRenderSettings(exact.getRenderSettings().withLightCutoff(0)).renderImage();
        Camera cut = SceneLoader.build(d, file).camera();
        cut.setRenderSettings(cut.getRenderSettings().withLightCutoff(CUTOFF)).renderImage();
        assertWithinCutoff(name, exact, cut);
        assertEquals(0, exact.getLastStatistics().rays().lightsCutOff, "a cut-off of 0 sets nothing aside");
    }

    @Test
    void manyDimLightsAreSetAsideWithinTheBound() {
        Camera exact = manyLights().build();
        exact.setRenderSettings(RenderSettings.DEFAULT.withLightCutoff(0)).renderImage();
        Camera cut = manyLights().build().renderImage();
        RayCounters rays = cut.getLastStatistics().rays();
        assertTrue(rays.lightsCutOff > 0, "the far lights are set aside somewhere");
        assertTrue(rays.shadowRaysCutOff >= rays.lightsCutOff, "each set-aside light saves a shadow ray or more");
        assertEquals(
                exact.getLastStatistics().rays().shadow,
                rays.shadow + rays.shadowRaysCutOff,
                "hard lights: the shadow rays saved are exactly the rays not fired");
        assertWithinCutoff("many dim lights", exact, cut);
        assertTrue(
                cut.getLastStatistics()
                        .format()
                        .contains(String.format(
                                java.util.Locale.ROOT,
                                "cut-off: %,d lights too faint to matter at a shading point were not sampled (%,d shadow rays",
                                rays.lightsCutOff,
                                rays.shadowRaysCutOff)),
                cut.getLastStatistics().format());
        assertTrue(
                cut.getLastStatistics().plan().contains("light cut-off"),
                cut.getLastStatistics().plan());
    }

    @Test
    void setAsideLightsAreTheSameForAnyThreadCount() {
        Camera one = manyLights().setThreads(1).build().renderImage();
        Camera three = manyLights().setThreads(3).build().renderImage();
        assertEquals(null, FeatureScenes.firstDifference(one.getImage(), three.getImage()));
        assertEquals(
                one.getLastStatistics().rays().lightsCutOff,
                three.getLastStatistics().rays().lightsCutOff);
    }

    @Test
    void aMaterialThatAmplifiesLightTurnsTheCutoffOff() {
        Scene scene = manyLightsScene();
        scene.geometries.add(new Sphere(new Point(0, 0, 40), 5)
                .setMaterial(new Material().setKt(1.5).setKd(0.2)));
        Camera camera = camera(scene).build().renderImage();
        assertEquals(0, camera.getLastStatistics().rays().lightsCutOff);
        assertTrue(camera.getLastStatistics().plan().contains("light cut-off off: a material has kT > 1"));
    }

    /** A floor and spheres under a row of 40 weak lamps reaching far down a long floor. */
    private static Scene manyLightsScene() {
        Scene scene = new Scene("many lights").setAmbientLight(new AmbientLight(new Color(10, 10, 10)));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.6)));
        for (int i = 0; i < 8; i++) {
            scene.geometries.add(new Sphere(new Point(-40 + 10 * i, 60 * i, 6), 6)
                    .setMaterial(new Material().setKd(0.5).setKs(0.3).setShininess(30)));
        }
        for (int i = 0; i < 40; i++) {
            scene.lights.add(new PointLight(new Color(200, 180, 150), new Point(i % 2 == 0 ? -30 : 30, 25 * i, 25))
                    .setKq(0.01));
        }
        return scene;
    }

    private static Camera.Builder camera(Scene scene) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -60, 30))
                .setDirection(new Point(0, 200, 0), Vector.AXIS_Z)
                .setVpDistance(100)
                .setVpSize(120, 80)
                .setResolution(72, 48)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    private static Camera.Builder manyLights() {
        return camera(manyLightsScene());
    }

    /** Every linear channel within the cut-off, every 8-bit channel within one step; prints how many changed. */
    private static void assertWithinCutoff(String name, Camera exact, Camera cut) {
        ImageWriter a = exact.getImage(), b = cut.getImage();
        double worst = FeatureScenes.maxDifference(a, b);
        assertTrue(worst < CUTOFF, name + ": a linear channel moved by " + worst + " display steps");
        BufferedImage p = a.toBufferedImage(), q = b.toBufferedImage();
        int changed = 0, most = 0;
        for (int y = 0; y < p.getHeight(); y++) {
            for (int x = 0; x < p.getWidth(); x++) {
                int d = 0;
                for (int shift = 0; shift < 24; shift += 8) {
                    d = Math.max(d, Math.abs((p.getRGB(x, y) >> shift & 255) - (q.getRGB(x, y) >> shift & 255)));
                }
                if (d > 0) changed++;
                most = Math.max(most, d);
            }
        }
        assertTrue(most <= 1, name + ": an 8-bit channel moved by " + most + " steps");
        System.out.printf(
                "light cut-off %s on %s: %d of %d pixels differ by one step (largest linear change %.3f);"
                        + " %,d lights set aside, %,d shadow rays saved%n",
                CUTOFF,
                name,
                changed,
                p.getWidth() * p.getHeight(),
                worst,
                cut.getLastStatistics().rays().lightsCutOff,
                cut.getLastStatistics().rays().shadowRaysCutOff);
    }
}
