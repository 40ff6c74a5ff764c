package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static renderer.RenderTesting.assertColor;

import geometries.Polygon;
import geometries.Sphere;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * A glass sphere (kT 0.9, index 1.5) in front of a square mirror (kR 0.8), seen from (0,0,10). Three emissive
 * spheres stand behind the camera, visible only in the mirror (the green one only through the glass). No light sources: every pixel is a product of kT
 * and kR factors times an emission or the background, which an independent little tracer (Snell's law and mirror
 * reflection written out here) predicts for every pixel whose path stays clear of silhouettes and edges.
 */
class ReflectionRefractionRenderTest {
    private static final int N = 101;
    private static final double KT = 0.9, KR = 0.8, IOR = 1.5;
    private static final Point GLASS = new Point(0, 0, 0);
    private static final double GLASS_R = 2;
    private static final Point GREEN = new Point(0, 0, 20), YELLOW = new Point(14, -6, 25), RED = new Point(-12, 8, 22);
    private static final double GREEN_R = 3, YELLOW_R = 6, RED_R = 5;
    private static final Color GREEN_E = new Color(0, 200, 0), YELLOW_E = new Color(200, 200, 0);
    private static final Color RED_E = new Color(220, 30, 30);
    private static final Color BACKGROUND = new Color(0, 0, 50);
    private static final double MIRROR_Z = -5, MIRROR_HALF = 8;
    private static final double MARGIN = 1e-6;

    @Test
    void glassSphereInFrontOfAMirror() {
        Scene scene = new Scene("glass and mirror").setBackground(BACKGROUND);
        scene.geometries.add(
                new Sphere(GLASS, GLASS_R).setMaterial(new Material().setKt(KT).setIndexOfRefraction(IOR)),
                new Polygon(
                                new Point(-MIRROR_HALF, -MIRROR_HALF, MIRROR_Z),
                                new Point(MIRROR_HALF, -MIRROR_HALF, MIRROR_Z),
                                new Point(MIRROR_HALF, MIRROR_HALF, MIRROR_Z),
                                new Point(-MIRROR_HALF, MIRROR_HALF, MIRROR_Z))
                        .setMaterial(new Material().setKr(KR)),
                new Sphere(GREEN, GREEN_R).setEmission(GREEN_E),
                new Sphere(YELLOW, YELLOW_R).setEmission(YELLOW_E),
                new Sphere(RED, RED_R).setEmission(RED_E));
        Camera camera = RenderTesting.render(RenderTesting.topDown(scene, N).build(), "glass-mirror");

        // the centre pixel: straight through the glass (normal incidence), back from the mirror, through the glass
        // again and on to the green sphere behind the camera: kT^4 kR green
        assertColor(GREEN_E.scale(KT * KT * KT * KT * KR), camera.getImage().getPixel(N / 2, N / 2), 1e-9, "centre");

        int decided = 0, glassPixels = 0, redInMirror = 0, yellowInMirror = 0, greenThroughGlass = 0;
        int backgroundInMirror = 0;
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                Ray ray = camera.constructRay(N, N, j, i);
                Trace expected = new Trace();
                Color color = expected.trace(ray.getHead(), ray.getDirection(), false, 0);
                if (color == null) continue; // the path grazes a silhouette or an edge: not decided here
                decided++;
                Color actual = camera.getImage().getPixel(j, i);
                assertColor(color, actual, 1e-6, "pixel " + j + "," + i + " path " + expected.path);
                if (expected.path.startsWith("G")) glassPixels++;
                if (expected.path.equals("M-red")) redInMirror++;
                if (expected.path.equals("M-background")) backgroundInMirror++;
                if (expected.path.endsWith("-green")) greenThroughGlass++;
                if (expected.path.equals("M-yellow")) yellowInMirror++;
            }
        }
        assertTrue(decided > 0.9 * N * N, "most pixels decided: " + decided);
        assertTrue(glassPixels > 250, "pixels through the glass (a disc of radius ~10 px): " + glassPixels);
        // the emitters stand behind the camera: the mirror is the only way to see them
        assertTrue(
                redInMirror > 60 && yellowInMirror > 60,
                "reflected colours present in the mirror: red " + redInMirror + ", yellow " + yellowInMirror);
        assertTrue(greenThroughGlass > 10, "green seen through the glass and the mirror: " + greenThroughGlass);
        // spot checks where the reflections appear (computed from the virtual images behind the mirror)
        Color red = camera.getImage().getPixel(N / 2 - 14, N / 2 - 10);
        assertColor(RED_E.scale(KR), red, 1e-9, "red reflection");
        Color yellow = camera.getImage().getPixel(N / 2 + 16, N / 2 + 7);
        assertColor(YELLOW_E.scale(KR), yellow, 1e-9, "yellow reflection");
        assertTrue(backgroundInMirror > 1000, "background reflected (dimmed by kR): " + backgroundInMirror);
    }

    /** An independent tracer of this scene; null when a path passes within the margin of a decision boundary. */
    private static final class Trace {
        String path = "";

        Color trace(Point o, Vector d, boolean insideGlass, int depth) {
            assertTrue(depth < 9, "paths in this scene are short");
            double tGlass = sphere(o, d, GLASS, GLASS_R, insideGlass);
            double tMirror = mirror(o, d);
            double tGreen = sphere(o, d, GREEN, GREEN_R, false);
            double tYellow = sphere(o, d, YELLOW, YELLOW_R, false);
            double tRed = sphere(o, d, RED, RED_R, false);
            if (Double.isNaN(tGlass)
                    || Double.isNaN(tMirror)
                    || Double.isNaN(tGreen)
                    || Double.isNaN(tYellow)
                    || Double.isNaN(tRed)) {
                return null;
            }
            double t = Math.min(Math.min(tGlass, tMirror), Math.min(tGreen, Math.min(tYellow, tRed)));
            if (t == Double.POSITIVE_INFINITY) {
                path += "-background";
                return BACKGROUND;
            }
            Point p = o.add(d.scale(t));
            if (t == tGreen) {
                path += "-green";
                return GREEN_E;
            }
            if (t == tYellow) {
                path += "-yellow";
                return YELLOW_E;
            }
            if (t == tRed) {
                path += "-red";
                return RED_E;
            }
            if (t == tMirror) {
                path += "M";
                Vector r = new Vector(d.x, d.y, -d.z); // mirror in z = const
                Color c = trace(p, r, false, depth + 1);
                return c == null ? null : c.scale(KR);
            }
            path += "G";
            Vector n = p.subtract(GLASS).normalize(); // outward
            Vector facing = insideGlass ? n.scale(-1) : n;
            double eta = insideGlass ? IOR : 1 / IOR;
            double cosI = -d.dotProduct(facing);
            double k = 1 - eta * eta * (1 - cosI * cosI);
            if (k < 1e-6) return null; // near or beyond the critical angle: not in this scene's decided paths
            Vector refracted =
                    d.scale(eta).add(facing.scale(eta * cosI - Math.sqrt(k))).normalize();
            Color c = trace(p, refracted, !insideGlass, depth + 1);
            return c == null ? null : c.scale(KT);
        }

        /** Nearest t > 1e-9 with the sphere; infinity if clear by the margin; NaN if within it. */
        private static double sphere(Point o, Vector d, Point c, double r, boolean inside) {
            Vector f = null;
            try {
                f = o.subtract(c);
            } catch (IllegalArgumentException atCentre) {
                return r;
            }
            double b = -f.dotProduct(d);
            double dist = Math.sqrt(Math.max(0, f.lengthSquared() - b * b));
            if (!inside && Math.abs(dist - r) < MARGIN) return Double.NaN;
            if (dist >= r) return Double.POSITIVE_INFINITY;
            double h = Math.sqrt(r * r - dist * dist);
            double t0 = b - h, t1 = b + h;
            if (t0 > 1e-9) return t0;
            if (t1 > 1e-9) return t1;
            return Double.POSITIVE_INFINITY;
        }

        private static double mirror(Point o, Vector d) {
            if (d.z == 0) return Double.POSITIVE_INFINITY;
            double t = (MIRROR_Z - o.z) / d.z;
            if (t <= 1e-9) return Double.POSITIVE_INFINITY;
            double x = o.x + t * d.x, y = o.y + t * d.y;
            double inside = MIRROR_HALF - Math.max(Math.abs(x), Math.abs(y));
            if (Math.abs(inside) < MARGIN) return Double.NaN;
            return inside > 0 ? t : Double.POSITIVE_INFINITY;
        }
    }

    @Test
    void refractionFollowsSnellsLawAndReflectsTotallyBeyondTheCriticalAngle() {
        Vector n = Vector.AXIS_Z;
        // entering glass at 45 degrees: sin t = sin 45 / 1.5
        Vector v = new Vector(1, 0, -1).normalize();
        Vector t = Optics.refract(v, n, v.dotProduct(n), 1.5);
        assertEquals(Math.sin(Math.PI / 4) / 1.5, t.x / t.length(), 1e-12, "sin of the refracted angle");
        assertTrue(t.z < 0, "continues into the glass");
        // leaving glass at 30 degrees: sin t = 1.5 sin 30 = 0.75
        Vector out = new Vector(Math.sin(Math.PI / 6), 0, Math.cos(Math.PI / 6));
        Vector t2 = Optics.refract(out, n, out.dotProduct(n), 1.5);
        assertEquals(0.75, t2.x / t2.length(), 1e-12);
        assertTrue(t2.z > 0);
        // leaving glass at 60 degrees: 1.5 sin 60 > 1, total internal reflection
        Vector steep = new Vector(Math.sin(Math.PI / 3), 0, Math.cos(Math.PI / 3));
        Vector tir = Optics.refract(steep, n, steep.dotProduct(n), 1.5);
        Vector mirrored = new Vector(steep.x, 0, -steep.z);
        assertEquals(mirrored.x, tir.x / tir.length(), 1e-12);
        assertEquals(mirrored.z, tir.z / tir.length(), 1e-12);
        // index 1 goes straight through, bit for bit
        assertEquals(v, Optics.refract(v, n, v.dotProduct(n), 1.0));
        // reflection
        Vector r = Optics.reflect(v, n, v.dotProduct(n));
        assertEquals(v.x, r.x, 1e-15);
        assertEquals(-v.z, r.z, 1e-15);
    }
}
