package robustness;

import geometries.Cylinder;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerType;
import scene.Scene;

/**
 * Renders one small scene (spheres, a glass sphere, a mirror polygon, a triangle, a cylinder on a floor, a point
 * light) translated by an offset, camera and lights included. Exact arithmetic would give the same image at any
 * offset; doubles lose about {@code offset * 2^-53} of absolute precision, so a robust renderer changes only a few
 * pixels where a ray grazes an edge.
 */
public final class TranslationProbe {
    /** How one image differs from another, and how many of its pixels are not finite. */
    public record Result(double offset, double differingFraction, double rms, double max, long nonFinitePixels) {}

    private TranslationProbe() {}

    /**
     * The scene rendered at {@code offset} (added to every coordinate), {@code size} pixels square.
     *
     * @param offset the translation scale, added to every coordinate; 0 renders the scene at the origin
     * @param size the image width and height in pixels
     * @param useBvh true to search with the BVH, false by brute force
     * @return the rendered image
     */
    public static ImageWriter render(double offset, int size, boolean useBvh) {
        Vector o = new Vector(offset == 0 ? 1 : offset, offset == 0 ? 1 : offset * 0.7, offset == 0 ? 1 : offset * 0.4);
        double k = offset == 0 ? 0 : 1;
        Scene scene = new Scene("translation").setAmbientLight(new AmbientLight(new Color(25, 25, 25)));
        scene.geometries.add(
                new Plane(at(0, 0, 0, o, k), Vector.AXIS_Z)
                        .setMaterial(new Material().setKd(0.6).setKr(0.2)),
                new Sphere(at(-20, 10, 12, o, k), 12)
                        .setMaterial(new Material().setKd(0.6).setKs(0.4).setShininess(40)),
                new Sphere(at(12, -5, 9, o, k), 9)
                        .setMaterial(new Material().setKd(0.1).setKt(0.8).setIndexOfRefraction(1.5)),
                new Polygon(at(-40, 40, 0, o, k), at(40, 40, 0, o, k), at(40, 42, 40, o, k), at(-40, 42, 40, o, k))
                        .setMaterial(new Material().setKd(0.2).setKr(0.6)),
                new Triangle(at(20, 15, 0, o, k), at(38, 20, 0, o, k), at(28, 18, 25, o, k))
                        .setEmission(new Color(60, 40, 10))
                        .setMaterial(new Material().setKd(0.5)),
                new Cylinder(4, new Ray(at(-5, 25, 0, o, k), Vector.AXIS_Z), 30)
                        .setMaterial(new Material().setKd(0.5).setKs(0.3).setShininess(20)));
        scene.lights.add(new PointLight(new Color(500, 480, 420), at(-30, -40, 80, o, k)).setKl(0.002));
        return Camera.getBuilder()
                .setLocation(at(0, -110, 45, o, k))
                .setDirection(at(0, 10, 12, o, k), Vector.AXIS_Z)
                .setVpDistance(100)
                .setVpSize(90, 90)
                .setResolution(size, size)
                .setBvh(useBvh)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build()
                .renderImage()
                .getImage();
    }

    private static Point at(double x, double y, double z, Vector offset, double k) {
        return new Point(x + k * offset.x, y + k * offset.y, z + k * offset.z);
    }

    /**
     * Compares the render at {@code offset} with the one at the origin; a pixel differs by more than 1 of 255.
     *
     * @param reference the render at the origin
     * @param offset the offset of {@code image}, copied into the result
     * @param image the render at {@code offset}, of the same size as {@code reference}
     * @return the fraction of differing pixels, the RMS and largest channel difference (of 255) and the non-finite
     *     pixels
     */
    public static Result compare(ImageWriter reference, double offset, ImageWriter image) {
        long differing = 0, nonFinite = 0;
        double sum = 0, max = 0;
        int n = image.getNx() * image.getNy();
        for (int y = 0; y < image.getNy(); y++) {
            for (int x = 0; x < image.getNx(); x++) {
                Color a = reference.getPixel(x, y), b = image.getPixel(x, y);
                if (!b.isFinite()) nonFinite++;
                double d = Math.max(
                        Math.abs(clamp(a.getR()) - clamp(b.getR())),
                        Math.max(
                                Math.abs(clamp(a.getG()) - clamp(b.getG())),
                                Math.abs(clamp(a.getB()) - clamp(b.getB()))));
                if (d > 1) differing++;
                sum += d * d;
                max = Math.max(max, d);
            }
        }
        return new Result(offset, (double) differing / n, Math.sqrt(sum / n), max, nonFinite);
    }

    private static double clamp(double v) {
        return Math.max(0, Math.min(255, v));
    }
}
