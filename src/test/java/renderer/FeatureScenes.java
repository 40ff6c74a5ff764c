package renderer;

import geometries.Plane;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Small scenes made to exercise one sampled effect each, and image helpers for the tests that use them. */
final class FeatureScenes {
    static final Color WHITE = new Color(255, 255, 255);

    private FeatureScenes() {}

    /**
     * A floor lit by one light beside a sphere that casts a long shadow to +x of the origin: from x = 16 to 80 by
     * the tangent lines, centred near x = 48 on y = 0.
     */
    static Scene shadowScene(PointLight light, Material occluder) {
        Scene scene = new Scene("shadow").setAmbientLight(new AmbientLight(new Color(40, 40, 40)));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.8)));
        if (occluder != null) {
            scene.geometries.add(new Sphere(new Point(0, 0, 20), 8)
                    .setEmission(new Color(0, 0, 80))
                    .setMaterial(occluder));
        }
        scene.lights.add(light);
        return scene;
    }

    static PointLight shadowLight() {
        return new PointLight(new Color(300, 300, 300), new Point(-60, 0, 50));
    }

    /** Looks straight down on the shadow of {@link #shadowScene}. */
    static Camera.Builder shadowCamera(Scene scene, int resolution) {
        return Camera.getBuilder()
                .setLocation(new Point(48, 0, 400))
                .setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                .setVpDistance(400)
                .setVpSize(100, 100)
                .setResolution(resolution, resolution)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    /**
     * A camera over {@link #shadowScene} (with {@code occluder}, or none) whose pixels take 4 HALTON samples over their
     * area, rendered once so that its tracer is prepared: for tests that drive a {@link ProgressiveSampler} by hand.
     */
    static Camera areaSampledShadowCamera(Material occluder, int nX, int nY) {
        Camera camera = shadowCamera(shadowScene(shadowLight(), occluder), nX)
                .setResolution(nX, nY)
                .build()
                .setSamplingConfig(new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.HALTON));
        camera.renderImage();
        return camera;
    }

    /** Mean of the three channels. */
    static double brightness(Color c) {
        return (c.getR() + c.getG() + c.getB()) / 3;
    }

    static double brightness(ImageWriter image, int x, int y) {
        return brightness(image.getPixel(x, y));
    }

    /** Whether two images have the same linear pixels, bit for bit. */
    static boolean identical(ImageWriter a, ImageWriter b) {
        return firstDifference(a, b) == null;
    }

    /** The first pixel where the images differ, as "x,y: a vs b", or null. */
    static String firstDifference(ImageWriter a, ImageWriter b) {
        if (a.getNx() != b.getNx() || a.getNy() != b.getNy()) return "sizes differ";
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                if (!a.getPixel(x, y).equals(b.getPixel(x, y))) {
                    return x + "," + y + ": " + a.getPixel(x, y) + " vs " + b.getPixel(x, y);
                }
            }
        }
        return null;
    }

    /** Largest channel difference between the images. */
    static double maxDifference(ImageWriter a, ImageWriter b) {
        double max = 0;
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                Color p = a.getPixel(x, y), q = b.getPixel(x, y);
                max = Math.max(max, Math.abs(p.getR() - q.getR()));
                max = Math.max(max, Math.abs(p.getG() - q.getG()));
                max = Math.max(max, Math.abs(p.getB() - q.getB()));
            }
        }
        return max;
    }

    /** Root mean square channel difference between the images. */
    static double rmsDifference(ImageWriter a, ImageWriter b) {
        double sum = 0;
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                Color p = a.getPixel(x, y), q = b.getPixel(x, y);
                double dr = p.getR() - q.getR(), dg = p.getG() - q.getG(), db = p.getB() - q.getB();
                sum += dr * dr + dg * dg + db * db;
            }
        }
        return Math.sqrt(sum / (3.0 * a.getNx() * a.getNy()));
    }
}
