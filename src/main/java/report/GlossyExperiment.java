package report;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import java.util.List;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * Glossy reflection: a rough mirror floor reflecting coloured spheres and a bright panel; one pixel sample, so
 * only the reflection cone is sampled.
 */
public final class GlossyExperiment implements Experiment {
    @Override
    public String name() {
        return "glossy reflection";
    }

    @Override
    public String slug() {
        return "glossy";
    }

    @Override
    public String sampleUnit() {
        return "reflection rays per glossy hit";
    }

    @Override
    public List<Variant> variants() {
        return List.of(Variant.GRID, Variant.JITTERED, Variant.RANDOM, Variant.HALTON);
    }

    @Override
    public Camera camera(Variant variant, int samples, int width, int height) {
        return builder(new SamplingConfig(samples, TargetShape.CIRCLE, variant.pattern()), width, height);
    }

    @Override
    public Camera reference(int width, int height) {
        return builder(new SamplingConfig(1024, TargetShape.CIRCLE, SamplingPattern.JITTERED), width, height);
    }

    @Override
    public double[] crop() {
        return new double[] {0.25, 0.5, 0.45, 0.45};
    }

    private static Camera builder(SamplingConfig glossy, int width, int height) {
        Scene scene = new Scene("glossy").setAmbientLight(new AmbientLight(new Color(25, 25, 30)));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setEmission(new Color(10, 10, 12))
                        .setMaterial(new Material().setKd(0.2).setKr(0.7).setRoughness(0.12)),
                new Sphere(new Point(-15, 30, 8), 8).setEmission(new Color(200, 40, 30)),
                new Sphere(new Point(8, 40, 6), 6).setEmission(new Color(30, 160, 220)),
                new Polygon(new Point(-40, 70, 0), new Point(40, 70, 0), new Point(40, 70, 12), new Point(-40, 70, 12))
                        .setEmission(new Color(240, 230, 200)));
        scene.lights.add(new PointLight(new Color(200, 200, 200), new Point(0, 0, 60)));
        return Camera.getBuilder()
                .setLocation(new Point(0, -40, 18))
                .setDirection(new Point(0, 40, 2), Vector.AXIS_Z)
                .setVpDistance(60)
                .setVpSize(64, 48)
                .setResolution(width, height)
                .setRenderSettings(RenderSettings.DEFAULT.withGlossySampling(glossy))
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
    }
}
