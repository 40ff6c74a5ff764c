package report;

import geometries.Cylinder;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import java.util.List;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.RenderSettings;
import renderer.sampling.SamplingPattern;
import scene.Scene;

/**
 * Soft shadows on a penumbra scene: a sphere, a thin pole and a floating square over a floor, seen from above,
 * under one disk light; one camera ray per pixel, so only the light's disk is sampled.
 */
public final class SoftShadowExperiment implements Experiment {
    @Override
    public String name() {
        return "soft shadows";
    }

    @Override
    public String slug() {
        return "shadows";
    }

    @Override
    public String sampleUnit() {
        return "shadow rays per shading point";
    }

    @Override
    public List<Variant> variants() {
        return List.of(
                Variant.GRID,
                Variant.JITTERED,
                Variant.RANDOM,
                Variant.HALTON,
                new Variant(SamplingPattern.JITTERED, true));
    }

    @Override
    public Camera camera(Variant variant, int samples, int width, int height) {
        return builder(samples, width, height)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(variant.pattern(), variant.adaptive()))
                .build();
    }

    @Override
    public Camera reference(int width, int height) {
        return builder(4096, width, height)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, false))
                .build();
    }

    @Override
    public double[] crop() {
        return new double[] {0.05, 0.0, 0.4, 0.5};
    }

    private static Camera.Builder builder(int samples, int width, int height) {
        Scene scene = new Scene("penumbra").setAmbientLight(new AmbientLight(new Color(30, 30, 35)));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.8)),
                new Sphere(new Point(-20, 5, 18), 9)
                        .setMaterial(new Material().setKd(0.6))
                        .setEmission(new Color(60, 20, 20)),
                new Cylinder(1.2, new Ray(new Point(10, -12, 0), Vector.AXIS_Z), 30)
                        .setMaterial(new Material().setKd(0.6)),
                new Polygon(new Point(5, 10, 14), new Point(20, 10, 14), new Point(20, 24, 14), new Point(5, 24, 14))
                        .setMaterial(new Material().setKd(0.6))
                        .setEmission(new Color(20, 40, 60)));
        scene.lights.add(new PointLight(new Color(380, 370, 350), new Point(-30, -25, 60))
                .setKl(0.001)
                .setRadius(12)
                .setNumSamples(samples));
        return Camera.getBuilder()
                .setLocation(new Point(10, 10, 200))
                .setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                .setVpDistance(200)
                .setVpSize(80, 60)
                .setResolution(width, height)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }
}
