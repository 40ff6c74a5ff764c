package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static renderer.RenderTesting.assertColor;
import static renderer.RenderTesting.distanceToSegment;
import static renderer.RenderTesting.floorPoint;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * Hard shadows of a point light on a matte floor, cast by an opaque sphere (full shadow), a transparent square
 * with kT = 0.5 (crossed once: half the light) and a transparent sphere with kT = 0.5 (crossed twice: a
 * quarter). Each floor pixel is classified analytically from the segment between its floor point and the light.
 */
class ShadowRenderTest {
    private static final int N = 150;
    private static final double KD = 0.8, MARGIN = 0.05;
    private static final Color AMBIENT = new Color(25, 25, 25);
    private static final Color I = new Color(255, 255, 255);
    private static final Point LIGHT = new Point(0, -6, 8);
    private static final Point OPAQUE = new Point(-4, 0, 2), GLASS = new Point(0, 3, 2);
    private static final double R = 1;
    /** The transparent square: z = 3, 2 < x < 5, -1.5 < y < 1.5. */
    private static final double SQ_Z = 3, SQ_X0 = 2, SQ_X1 = 5, SQ_Y = 1.5;

    /** 1 inside the square by the margin, 0 outside by the margin, -1 undecided, where the segment meets z=3. */
    private static int crossesSquare(Point from, Point to) {
        double s = (SQ_Z - from.z) / (to.z - from.z);
        if (s <= 0 || s >= 1) return 0;
        double x = from.x + s * (to.x - from.x), y = from.y + s * (to.y - from.y);
        double inside = Math.min(Math.min(x - SQ_X0, SQ_X1 - x), SQ_Y - Math.abs(y));
        return inside > MARGIN ? 1 : inside < -MARGIN ? 0 : -1;
    }

    /** 1 if the segment passes through the sphere by the margin, 0 if it clears it, -1 undecided. */
    private static int crossesSphere(Point c, Point from, Point to) {
        double d = distanceToSegment(c, from, to);
        return d < R - MARGIN ? 1 : d > R + MARGIN ? 0 : -1;
    }

    @Test
    void opaqueAndTransparentOccluders() {
        Scene scene = new Scene("shadows").setAmbientLight(new AmbientLight(AMBIENT, 1));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(KD)));
        scene.geometries.add(new Sphere(OPAQUE, R).setMaterial(new Material().setKd(0.5)));
        scene.geometries.add(new Sphere(GLASS, R).setMaterial(new Material().setKt(0.5)));
        scene.geometries.add(new Polygon(
                        new Point(SQ_X0, -SQ_Y, SQ_Z),
                        new Point(SQ_X1, -SQ_Y, SQ_Z),
                        new Point(SQ_X1, SQ_Y, SQ_Z),
                        new Point(SQ_X0, SQ_Y, SQ_Z))
                .setMaterial(new Material().setKt(0.5)));
        scene.addLights(new PointLight(I, LIGHT));
        Camera camera = RenderTesting.render(RenderTesting.topDown(scene, N).build(), "shadows");
        Point eye = new Point(0, 0, RenderTesting.HEIGHT);

        int lit = 0, full = 0, half = 0, quarter = 0;
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                Point p = floorPoint(camera, j, i);
                // only floor pixels the camera sees directly
                if (crossesSphere(OPAQUE, eye, p) != 0
                        || crossesSphere(GLASS, eye, p) != 0
                        || crossesSquare(eye, p) != 0) {
                    continue;
                }
                int opaque = crossesSphere(OPAQUE, p, LIGHT);
                int glass = crossesSphere(GLASS, p, LIGHT);
                int square = crossesSquare(p, LIGHT);
                if (opaque < 0 || glass < 0 || square < 0) continue; // penumbra of rounding: undecided
                double visibility = opaque == 1 ? 0 : (glass == 1 ? 0.25 : 1) * (square == 1 ? 0.5 : 1);
                double cos = LIGHT.z / p.distance(LIGHT);
                Color expected = AMBIENT.add(I.scale(visibility * KD * cos));
                Color actual = camera.getImage().getPixel(j, i);
                assertColor(expected, actual, 1e-7, "pixel " + j + "," + i + " at " + p + " visibility " + visibility);
                if (visibility == 0) full++;
                else if (visibility == 1) lit++;
                else if (visibility == 0.5) half++;
                else if (visibility == 0.25) quarter++;
            }
        }
        assertTrue(
                full > 100 && half > 100 && quarter > 100 && lit > 5000,
                "all kinds of pixels present: lit " + lit + ", full " + full + ", half " + half + ", quarter "
                        + quarter);

        // the ordering the eye sees: full shadow < transparent shadow < lit floor
        int[] inFull = LightsRenderTest.pixelOf(-5.33, 2, N), inHalf = LightsRenderTest.pixelOf(5.6, 3.6, N);
        double fullShadow = RenderTesting.brightness(camera.getImage().getPixel(inFull[0], inFull[1]));
        double halfShadow = RenderTesting.brightness(camera.getImage().getPixel(inHalf[0], inHalf[1]));
        int[] beside = LightsRenderTest.pixelOf(5.6, -3.6, N);
        double litBeside = RenderTesting.brightness(camera.getImage().getPixel(beside[0], beside[1]));
        assertTrue(
                fullShadow < halfShadow && halfShadow < litBeside,
                "full " + fullShadow + " < half " + halfShadow + " < lit " + litBeside);
        assertColor(AMBIENT, camera.getImage().getPixel(inFull[0], inFull[1]), 1e-9, "the full shadow is ambient");
    }
}
