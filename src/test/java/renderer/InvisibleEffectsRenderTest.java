package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * Work whose result is exactly zero must not change the image: a soft light that is completely blocked, and a
 * rough mirror that reflects nothing but black background. Both render bit for bit like the scene without them,
 * also with jittered anti-aliasing and a lens (the camera's sample positions must not be disturbed by the
 * sampling the tracer does below them).
 */
class InvisibleEffectsRenderTest {
    private static final int N = 48;

    /** Floor, a few spheres at different heights and a roof above the camera (never seen). */
    private static Scene baseScene(String name) {
        Scene scene = new Scene(name).setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setEmission(new Color(20, 20, 30))
                        .setMaterial(new Material().setKd(0.6)),
                new Sphere(new Point(-3, 2, 1), 1).setEmission(new Color(180, 40, 40)),
                new Sphere(new Point(2, -2, 2), 1.2).setEmission(new Color(40, 180, 60)),
                new Sphere(new Point(3, 3, 0.5), 0.5).setEmission(new Color(200, 200, 40)),
                new Polygon(
                        new Point(-50, -50, 12),
                        new Point(50, -50, 12),
                        new Point(50, 50, 12),
                        new Point(-50, 50, 12)));
        scene.addLights(new DirectionalLight(new Color(60, 60, 60), new Vector(0.2, 0.3, -1)));
        return scene;
    }

    private static Color[][] render(Scene scene, SamplingConfig antiAliasing, boolean lens, String image) {
        Camera.Builder builder = RenderTesting.topDown(scene, N).setSamplingConfig(antiAliasing);
        if (lens) {
            builder.setDepthOfField(6, 0.6)
                    .setApertureSampling(new SamplingConfig(9, TargetShape.CIRCLE, SamplingPattern.JITTERED));
        }
        Camera camera = builder.build();
        camera.renderImage();
        if (image != null) camera.writeToImage("test-" + image);
        Color[][] pixels = new Color[N][N];
        for (int y = 0; y < N; y++)
            for (int x = 0; x < N; x++) pixels[y][x] = camera.getImage().getPixel(x, y);
        return pixels;
    }

    private static void assertIdentical(Color[][] expected, Color[][] actual, String what) {
        int differences = 0;
        String first = null;
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                if (!expected[y][x].equals(actual[y][x])) {
                    differences++;
                    if (first == null) first = x + "," + y + ": " + actual[y][x] + " instead of " + expected[y][x];
                }
            }
        }
        if (differences > 0) fail(what + ": " + differences + " pixels differ, first " + first);
    }

    @Test
    void aCompletelyBlockedSoftLightChangesNothing() {
        SamplingConfig jittered = new SamplingConfig(9, TargetShape.RECTANGLE, SamplingPattern.JITTERED);
        Color[][] without = render(baseScene("no extra light"), jittered, false, "invisible-light-without");
        // a soft light above the roof: every shadow ray toward it is blocked
        Scene scene = baseScene("blocked light");
        scene.addLights(new PointLight(new Color(500, 500, 500), new Point(0, 0, 20))
                .setRadius(2)
                .setNumSamples(16));
        Color[][] with = render(scene, jittered, false, "invisible-light-with");
        assertIdentical(without, with, "a blocked soft light with jittered anti-aliasing");
    }

    @Test
    void aRoughMirrorReflectingOnlyBlackChangesNothingThroughALens() {
        // a horizontal tile above everything else: its reflections go up, to the black background
        Scene smooth = baseScene("smooth tile");
        Scene rough = baseScene("rough tile");
        for (Scene s : new Scene[] {smooth, rough}) s.geometries.add(tile(s == rough ? 0.3 : 0));
        // without the roof, so that the background above is really black
        Scene smoothOpen = withoutRoof(smooth), roughOpen = withoutRoof(rough);
        Color[][] expected = render(smoothOpen, SamplingConfig.NONE, true, "invisible-glossy-smooth");
        Color[][] actual = render(roughOpen, SamplingConfig.NONE, true, "invisible-glossy-rough");
        assertIdentical(expected, actual, "a rough tile reflecting black, depth of field");
        // the tile is in view and out of focus
        assertTrue(!expected[N / 2][N / 2].equals(expected[0][0]));
    }

    private static Polygon tile(double roughness) {
        Polygon p = new Polygon(new Point(-1, -1, 3), new Point(1, -1, 3), new Point(1, 1, 3), new Point(-1, 1, 3));
        p.setEmission(new Color(60, 60, 160))
                .setMaterial(new Material().setKd(0.3).setKr(0.5).setRoughness(roughness));
        return p;
    }

    private static Scene withoutRoof(Scene scene) {
        Scene open = new Scene(scene.getName() + " open").setAmbientLight(scene.ambientLight);
        scene.geometries.getMembers().stream()
                .filter(g -> !(g instanceof Polygon p && p.getVertices().get(0).z == 12))
                .forEach(open.geometries::add);
        open.setLights(scene.lights);
        return open;
    }
}
