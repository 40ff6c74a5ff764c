package renderer;

import static org.junit.jupiter.api.Assertions.assertNull;

import geometries.Plane;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Every random sample derives from the scene seed and the pixel: 1, 2 and 4 threads give the same bits. */
class SamplingDeterminismTest {

    private static Scene scene() {
        Scene scene = new Scene("determinism").setAmbientLight(new AmbientLight(new Color(30, 30, 30)));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setMaterial(new Material().setKd(0.6).setKr(0.3).setRoughness(0.1)),
                new Sphere(new Point(0, 0, 15), 15)
                        .setEmission(new Color(20, 10, 10))
                        .setMaterial(new Material()
                                .setKd(0.3)
                                .setKt(0.5)
                                .setIndexOfRefraction(1.3)
                                .setRoughness(0.05)),
                new Sphere(new Point(30, 20, 10), 10)
                        .setMaterial(new Material().setKd(0.7).setKs(0.3).setShininess(30)));
        scene.lights.add(new PointLight(new Color(400, 400, 300), new Point(-40, -40, 80))
                .setKl(0.002)
                .setRadius(8)
                .setNumSamples(9));
        return scene;
    }

    private static ImageWriter render(SamplingPattern pattern, int threads) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -120, 60))
                .setDirection(new Point(0, 0, 10), Vector.AXIS_Z)
                .setVpDistance(100)
                .setVpSize(80, 80)
                .setResolution(40, 40)
                .setRayTracer(scene(), RayTracerType.SIMPLE)
                .setSamplingConfig(new SamplingConfig(4, TargetShape.RECTANGLE, pattern))
                .setDepthOfField(130, 2)
                .setApertureSampling(new SamplingConfig(2, TargetShape.CIRCLE, pattern))
                .setRenderSettings(RenderSettings.DEFAULT
                        .withShadowSampling(pattern, false)
                        .withGlossySampling(new SamplingConfig(4, TargetShape.CIRCLE, pattern)))
                .setThreads(threads)
                .build()
                .renderImage()
                .getImage();
    }

    @ParameterizedTest
    @EnumSource(SamplingPattern.class)
    void oneTwoAndFourThreadsGiveBitIdenticalImages(SamplingPattern pattern) {
        ImageWriter one = render(pattern, 1);
        assertNull(FeatureScenes.firstDifference(one, render(pattern, 2)), "2 threads, " + pattern);
        assertNull(FeatureScenes.firstDifference(one, render(pattern, 4)), "4 threads, " + pattern);
        assertNull(FeatureScenes.firstDifference(one, render(pattern, 1)), "a second run, " + pattern);
    }
}
