package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static renderer.RenderTesting.assertColor;
import static renderer.RenderTesting.floorPoint;

import geometries.Plane;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * One render per light type over a matte-and-glossy floor seen from above. Every pixel is compared with the Phong
 * model evaluated here by hand: emission + ambient + I(p) (kD |n.l| + kS max(0, -v.r)^shininess), with r the
 * mirror of l, for lights on the viewer's side of the floor only.
 */
class LightsRenderTest {
    private static final int N = 100;
    private static final Color EMISSION = new Color(10, 10, 10);
    private static final Color AMBIENT = new Color(20, 20, 20);
    private static final Color BASE = EMISSION.add(AMBIENT);
    private static final double KD = 0.6, KS = 0.4;
    private static final int SHININESS = 20;
    private static final Vector N_FLOOR = Vector.AXIS_Z;

    private static Scene floorScene(String name, LightSource... lights) {
        Scene scene = new Scene(name).setAmbientLight(new AmbientLight(AMBIENT, 1));
        scene.geometries.add(new Plane(Point.ZERO, N_FLOOR)
                .setEmission(EMISSION)
                .setMaterial(new Material().setKd(KD).setKs(KS).setShininess(SHININESS)));
        scene.addLights(lights);
        return scene;
    }

    /** Phong at floor point p lit by intensity i arriving along unit l (from the light toward p). */
    private static Color phong(Point p, Vector l, Color i) {
        Vector v = p.subtract(new Point(0, 0, RenderTesting.HEIGHT)).normalize();
        double nl = N_FLOOR.dotProduct(l), nv = N_FLOOR.dotProduct(v);
        if (nl * nv <= 0) return BASE; // light on the other side of the floor
        Vector r = l.subtract(N_FLOOR.scale(2 * nl));
        double specular = Math.pow(Math.max(0, -v.dotProduct(r)), SHININESS);
        return BASE.add(i.scale(KD * Math.abs(nl) + KS * specular));
    }

    private interface Expected {
        Color at(Point floor);
    }

    /** Renders, then compares every pixel with {@code expected}; returns the camera. */
    private static Camera renderAndCompare(Scene scene, String name, Expected expected) {
        Camera camera = RenderTesting.render(RenderTesting.topDown(scene, N).build(), name);
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                Point p = floorPoint(camera, j, i);
                assertColor(expected.at(p), camera.getImage().getPixel(j, i), 1e-7, name + " pixel " + j + "," + i);
            }
        }
        return camera;
    }

    @Test
    void directionalLightLightsTheFloorEvenlyAndOnlyFromAbove() {
        Color i = new Color(200, 150, 100);
        Vector down = new Vector(1, 0, -1).normalize();
        // a second directional light from below the floor must add nothing
        Scene scene = floorScene(
                "directional",
                new DirectionalLight(i, down),
                new DirectionalLight(new Color(500, 500, 500), Vector.AXIS_Z));
        Camera camera = renderAndCompare(scene, "light-directional", p -> phong(p, down, i));
        // diffuse 0.6 / sqrt 2 of the intensity everywhere; the highlight where the view mirrors the light
        Color somewhere = camera.getImage().getPixel(10, 50);
        assertTrue(somewhere.getR() > BASE.getR() + 0.6 / Math.sqrt(2) * 200 - 1e-6, somewhere.toString());
    }

    @Test
    void pointLightAttenuatesWithDistanceAndAngle() {
        Point position = new Point(2, 3, 4);
        Color i = new Color(300, 250, 200);
        PointLight light = new PointLight(i, position).setKl(0.05).setKq(0.01);
        // the same light below the floor adds nothing
        PointLight below = new PointLight(new Color(900, 900, 900), new Point(0, 0, -3));
        Camera camera = renderAndCompare(floorScene("point", light, below), "light-point", p -> {
            double d = p.distance(position);
            return phong(p, p.subtract(position).normalize(), i.scale(1 / (1 + 0.05 * d + 0.01 * d * d)));
        });
        // brightest right under the light, darker far away
        int[] under = pixelOf(2, 3, N), far = pixelOf(-9, -9, N);
        assertTrue(RenderTesting.brightness(camera.getImage().getPixel(under[0], under[1]))
                > 2 * RenderTesting.brightness(camera.getImage().getPixel(far[0], far[1])));
    }

    @Test
    void spotLightLightsOnlyInsideItsBeam() {
        Point position = new Point(0, 0, 5);
        Vector direction = new Vector(1, 0, -1).normalize();
        Color i = new Color(400, 300, 200);
        SpotLight spot = new SpotLight(i, position, direction).setNarrowBeam(3).setKq(0.005);
        Camera camera = renderAndCompare(floorScene("spot", spot), "light-spot", p -> {
            Vector l = p.subtract(position).normalize();
            double cos = direction.dotProduct(l);
            if (cos <= 0) return BASE;
            double d = p.distance(position);
            return phong(p, l, i.scale(Math.pow(cos, 3) / (1 + 0.005 * d * d)));
        });
        // behind the beam (x < -5: direction . l < 0) only emission and ambient, exactly
        for (int i2 = 0; i2 < N; i2 += 7) {
            int[] behind = pixelOf(-8, -9 + i2 * 0.18, N);
            assertColor(BASE, camera.getImage().getPixel(behind[0], behind[1]), 0, "behind the spot");
        }
        int[] inBeam = pixelOf(5, 0, N);
        assertTrue(RenderTesting.brightness(camera.getImage().getPixel(inBeam[0], inBeam[1]))
                > RenderTesting.brightness(BASE) + 50);
    }

    /** The pixel of an n x n top-down render whose ray meets the floor at about (x, y) (y up). */
    static int[] pixelOf(double x, double y, int n) {
        double size = 20.0 / n;
        return new int[] {(int) Math.floor((x + 10) / size), (int) Math.floor((10 - y) / size)};
    }
}
