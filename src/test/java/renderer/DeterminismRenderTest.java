package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import geometries.Cylinder;
import geometries.Mesh;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * The same scene, with every effect and random sampling (jittered anti-aliasing, soft shadows, glossy
 * reflection), rendered with 1, 2 and 8 threads, with the BVH on and off, and with effect planning off: the pixels
 * must be identical bit for bit.
 */
class DeterminismRenderTest {
    private static final int N = 64;
    private static Color[][] reference;

    static Scene scene() {
        Scene scene = new Scene("determinism")
                .setBackground(new Color(10, 12, 30))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.05));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setEmission(new Color(20, 20, 20))
                        .setMaterial(new Material()
                                .setKd(0.5)
                                .setKs(0.2)
                                .setShininess(30)
                                .setKr(0.2)),
                new Sphere(new Point(-2, 1, 1.5), 1.5)
                        .setMaterial(new Material()
                                .setKd(0.05)
                                .setKs(0.5)
                                .setShininess(200)
                                .setKt(0.8)
                                .setIndexOfRefraction(1.5)),
                new Sphere(new Point(2, 2, 1.2), 1.2)
                        .setEmission(new Color(30, 10, 10))
                        .setMaterial(new Material()
                                .setKd(0.2)
                                .setKs(0.6)
                                .setShininess(100)
                                .setKr(0.6)
                                .setRoughness(0.05)),
                new Cylinder(0.6, new Ray(new Point(0, 4, 0), Vector.AXIS_Z), 3)
                        .setEmission(new Color(10, 40, 20))
                        .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(20)),
                new Polygon(new Point(-4, 6, 0), new Point(4, 6, 0), new Point(4, 6.5, 4), new Point(-4, 6.5, 4))
                        .setMaterial(new Material().setKd(0.2).setKr(0.5)),
                new Triangle(new Point(1, -1, 0), new Point(3, -0.5, 0), new Point(2, -0.8, 2))
                        .setEmission(new Color(60, 50, 10))
                        .setMaterial(new Material().setKd(0.6).setKt(0.3)),
                new Mesh(
                                new double[] {
                                    -0.5, -1, 0.8, 0.5, -1, 0.8, 0, -0.5, 0.8, 0, -1.5, 0.8, 0, -1, 1.8, 0, -1, -0.2
                                },
                                new int[] {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5})
                        .setEmission(new Color(20, 20, 60))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(50)));
        scene.addLights(
                new PointLight(new Color(300, 260, 220), new Point(-3, -3, 6))
                        .setKl(0.02)
                        .setRadius(0.8)
                        .setNumSamples(9),
                new SpotLight(new Color(250, 250, 350), new Point(4, -4, 5), new Vector(-1, 1, -1.2))
                        .setNarrowBeam(3)
                        .setRadius(0.3)
                        .setNumSamples(4),
                new DirectionalLight(new Color(40, 40, 50), new Vector(0.3, 1, -1)));
        return scene;
    }

    private static Color[][] render(int threads, RenderSettings settings, String name) {
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -12, 6))
                .setDirection(new Point(0, 1.5, 1), Vector.AXIS_Z)
                .setVpDistance(10)
                .setVpSize(12, 12)
                .setResolution(N, N)
                .setRayTracer(scene(), RayTracerType.SIMPLE)
                .setSamplingConfig(new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .setRenderSettings(settings.withGlossySampling(
                        new SamplingConfig(4, TargetShape.CIRCLE, SamplingPattern.JITTERED)))
                .setThreads(threads)
                .build();
        camera.renderImage();
        if (name != null) camera.writeToImage("test-" + name);
        assertEquals(threads, camera.getLastStatistics().threads());
        Color[][] pixels = new Color[N][N];
        for (int y = 0; y < N; y++)
            for (int x = 0; x < N; x++) pixels[y][x] = camera.getImage().getPixel(x, y);
        return pixels;
    }

    @BeforeAll
    static void renderReference() {
        reference = render(1, RenderSettings.DEFAULT, "determinism");
    }

    private static void assertIdentical(Color[][] actual, String what) {
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                // Color.equals compares the doubles exactly (Double.compare)
                if (!reference[y][x].equals(actual[y][x])) {
                    fail(what + ": pixel " + x + "," + y + " is " + actual[y][x] + " instead of " + reference[y][x]);
                }
            }
        }
    }

    @Test
    void theReferenceShowsSomething() {
        int distinct = 0;
        Color previous = null;
        for (Color[] row : reference) {
            for (Color c : row) {
                assertTrue(c.isFinite(), "finite pixel " + c);
                if (!c.equals(previous)) distinct++;
                previous = c;
            }
        }
        assertTrue(distinct > N * N / 2, "a varied image: " + distinct + " changes");
    }

    @Test
    void twoAndEightThreadsGiveTheSameBits() {
        assertIdentical(render(2, RenderSettings.DEFAULT, null), "2 threads");
        assertIdentical(render(8, RenderSettings.DEFAULT, null), "8 threads");
    }

    @Test
    void bruteForceGivesTheSameBitsAsTheBvh() {
        assertIdentical(render(2, RenderSettings.DEFAULT.withBvh(false), "determinism-brute"), "BVH off");
        assertIdentical(render(1, RenderSettings.DEFAULT.withBvhBuild(2, 1), null), "BVH with tiny leaves");
    }

    @Test
    void effectPlanningChangesTheCostNotTheImage() {
        assertIdentical(render(2, RenderSettings.DEFAULT.withPlanEffects(false), null), "planning off");
    }
}
