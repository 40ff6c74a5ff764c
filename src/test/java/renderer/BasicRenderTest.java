package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static renderer.RenderTesting.assertColor;

import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * A basic scene without light sources: every surface shows emission + ambient * kA, the background shows where
 * nothing is hit. Each pixel is classified analytically from its ray and compared exactly.
 */
class BasicRenderTest {
    private static final Color BACKGROUND = new Color(75, 127, 90);
    private static final Color AMBIENT = new Color(100, 50, 20);

    @Test
    void emissionAndAmbientWhereTheGeometryIsBackgroundElsewhere() {
        Sphere sphere = new Sphere(new Point(0, 0, -100), 50);
        sphere.setEmission(new Color(100, 0, 0)); // default kA = 1
        // behind the sphere, in the plane z = -150: one triangle up-left, one down-right
        Triangle upLeft =
                new Triangle(new Point(-150, 150, -150), new Point(-150, 20, -150), new Point(-20, 150, -150));
        upLeft.setEmission(new Color(0, 100, 0)).setMaterial(new Material().setKa(0.5));
        Triangle downRight =
                new Triangle(new Point(150, -150, -150), new Point(150, -20, -150), new Point(20, -150, -150));
        downRight.setEmission(new Color(0, 0, 100)).setMaterial(new Material().setKa(0));
        Scene scene = new Scene("basic").setBackground(BACKGROUND).setAmbientLight(new AmbientLight(AMBIENT, 1));
        scene.geometries.add(sphere, upLeft, downRight);
        Camera camera = RenderTesting.render(
                Camera.getBuilder()
                        .setLocation(Point.ZERO)
                        .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                        .setVpDistance(100)
                        .setVpSize(200, 200)
                        .setResolution(100, 100)
                        .setRayTracer(scene, RayTracerType.SIMPLE)
                        .build(),
                "basic");

        Color sphereColor = new Color(100 + 100, 50, 20);
        Color upLeftColor = new Color(50, 100 + 25, 10);
        Color downRightColor = new Color(0, 0, 100);
        int[] counts = new int[4];
        for (int i = 0; i < 100; i++) {
            for (int j = 0; j < 100; j++) {
                Ray ray = camera.constructRay(100, 100, j, i);
                Vector d = ray.getDirection();
                Color actual = camera.getImage().getPixel(j, i);
                String where = "pixel " + j + "," + i;
                // distance of the ray's line from the sphere centre (0,0,-100): |c x d|
                double dist = new Vector(0, 0, -100).crossProduct(d).length();
                // where the ray meets z = -150
                double x = -150 * d.x / d.z, y = -150 * d.y / d.z;
                if (dist < 50 - 0.5) {
                    assertColor(sphereColor, actual, 1e-9, where + " (sphere)");
                    counts[0]++;
                } else if (dist > 50 + 0.5) {
                    // the triangles: up-left is x <= -20, y >= 20 and above the line x - y = -170 (hypotenuse)
                    boolean inUpLeft = x > -150 + 1 && y < 150 - 1 && (y - x) > 170 + 1;
                    boolean inDownRight = x < 150 - 1 && y > -150 + 1 && (x - y) > 170 + 1;
                    boolean outside = (y - x) < 170 - 1 && (x - y) < 170 - 1;
                    if (inUpLeft) {
                        assertColor(upLeftColor, actual, 1e-9, where + " (up-left triangle)");
                        counts[1]++;
                    } else if (inDownRight) {
                        assertColor(downRightColor, actual, 1e-9, where + " (down-right triangle)");
                        counts[2]++;
                    } else if (outside) {
                        assertEquals(BACKGROUND, actual, where + " (background)");
                        counts[3]++;
                    }
                }
            }
        }
        // every class is well represented (the sphere covers a quarter of the view, pi/4 of it)
        assertTrue(counts[0] > 1500, "sphere pixels " + counts[0]);
        assertTrue(counts[1] > 50 && counts[2] > 50, "triangle pixels " + counts[1] + ", " + counts[2]);
        assertTrue(counts[3] > 3000, "background pixels " + counts[3]);
    }
}
