package report;

import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import java.util.List;
import primitives.Color;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * Anti-aliasing on an edge-heavy scene: a chequerboard floor receding to the horizon (where it aliases), a star of
 * thin wedges and a sphere, all flat emissive colours, so only the pixel footprint is sampled.
 */
public final class AntiAliasingExperiment implements Experiment {
    @Override
    public String name() {
        return "anti-aliasing";
    }

    @Override
    public String slug() {
        return "aa";
    }

    @Override
    public String sampleUnit() {
        return "camera rays per pixel";
    }

    @Override
    public List<Variant> variants() {
        return List.of(
                Variant.GRID,
                Variant.JITTERED,
                Variant.RANDOM,
                Variant.HALTON,
                new Variant(SamplingPattern.GRID, true));
    }

    @Override
    public Camera camera(Variant variant, int samples, int width, int height) {
        SamplingConfig config = new SamplingConfig(samples, TargetShape.RECTANGLE, variant.pattern());
        return builder(width, height)
                .setSamplingConfig(variant.adaptive() ? config.adaptive(4) : config)
                .build();
    }

    @Override
    public Camera reference(int width, int height) {
        return builder(width, height)
                .setSamplingConfig(new SamplingConfig(1024, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .build();
    }

    @Override
    public double[] crop() {
        return new double[] {0.45, 0.4, 0.4, 0.4};
    }

    private static Camera.Builder builder(int width, int height) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -60, 14))
                .setDirection(new Point(0, 40, 0), Vector.AXIS_Z)
                .setVpDistance(50)
                .setVpSize(64, 48)
                .setResolution(width, height)
                .setRayTracer(scene(), RayTracerType.SIMPLE);
    }

    static Scene scene() {
        Scene scene = new Scene("edges").setBackground(new Color(20, 30, 70));
        Color light = new Color(230, 220, 200), dark = new Color(40, 40, 50);
        double size = 8;
        for (int i = -12; i < 12; i++) {
            for (int j = -4; j < 40; j++) {
                double x = i * size, y = j * size;
                scene.geometries.add(new Polygon(
                                new Point(x, y, 0),
                                new Point(x + size, y, 0),
                                new Point(x + size, y + size, 0),
                                new Point(x, y + size, 0))
                        .setEmission((i + j & 1) == 0 ? light : dark));
            }
        }
        // A star of thin wedges standing up from the floor.
        Point centre = new Point(-10, 0, 16);
        for (int k = 0; k < 16; k++) {
            double a0 = 2 * Math.PI * k / 16, a1 = a0 + Math.PI / 32;
            scene.geometries.add(new Triangle(
                            centre,
                            new Point(centre.x + 12 * Math.cos(a0), centre.y, centre.z + 12 * Math.sin(a0)),
                            new Point(centre.x + 12 * Math.cos(a1), centre.y, centre.z + 12 * Math.sin(a1)))
                    .setEmission(new Color(250, 120, 40)));
        }
        scene.geometries.add(new Sphere(new Point(16, 10, 8), 8).setEmission(new Color(60, 200, 120)));
        return scene;
    }
}
