package report;

import geometries.Polygon;
import geometries.Sphere;
import java.util.List;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * Depth of field: spheres at several depths over a chequerboard, focused on the middle one; one pixel sample,
 * so only the lens is sampled.
 */
public final class DepthOfFieldExperiment implements Experiment {
    @Override
    public String name() {
        return "depth of field";
    }

    @Override
    public String slug() {
        return "dof";
    }

    @Override
    public String sampleUnit() {
        return "lens rays per pixel";
    }

    @Override
    public List<Variant> variants() {
        return List.of(Variant.GRID, Variant.JITTERED, Variant.RANDOM, Variant.HALTON);
    }

    @Override
    public Camera camera(Variant variant, int samples, int width, int height) {
        return builder(width, height)
                .setApertureSampling(new SamplingConfig(samples, TargetShape.CIRCLE, variant.pattern()))
                .build();
    }

    @Override
    public Camera reference(int width, int height) {
        return builder(width, height)
                .setApertureSampling(new SamplingConfig(1024, TargetShape.CIRCLE, SamplingPattern.JITTERED))
                .build();
    }

    @Override
    public double[] crop() {
        return new double[] {0.0, 0.35, 0.35, 0.5};
    }

    private static Camera.Builder builder(int width, int height) {
        Scene scene = new Scene("dof").setAmbientLight(new AmbientLight(new Color(60, 60, 60)));
        Color light = new Color(180, 170, 150), dark = new Color(30, 30, 40);
        for (int i = -6; i < 6; i++) {
            for (int j = 0; j < 16; j++) {
                double x = i * 10, y = j * 10;
                scene.geometries.add(new Polygon(
                                new Point(x, y, 0),
                                new Point(x + 10, y, 0),
                                new Point(x + 10, y + 10, 0),
                                new Point(x, y + 10, 0))
                        .setEmission((i + j & 1) == 0 ? light : dark)
                        .setMaterial(new Material().setKd(0.2)));
            }
        }
        Material matte = new Material().setKd(0.6).setKs(0.3).setShininess(30);
        scene.geometries.add(
                new Sphere(new Point(-22, 15, 7), 7)
                        .setEmission(new Color(120, 30, 30))
                        .setMaterial(matte),
                new Sphere(new Point(0, 55, 7), 7)
                        .setEmission(new Color(30, 120, 30))
                        .setMaterial(matte),
                new Sphere(new Point(25, 110, 7), 7)
                        .setEmission(new Color(30, 30, 120))
                        .setMaterial(matte));
        scene.lights.add(new DirectionalLight(new Color(200, 200, 190), new Vector(-1, 1, -2)));
        return Camera.getBuilder()
                .setLocation(new Point(0, -40, 20))
                .setDirection(new Point(0, 55, 4), Vector.AXIS_Z)
                .setVpDistance(60)
                .setVpSize(64, 48)
                .setResolution(width, height)
                .setDepthOfField(96, 3)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }
}
