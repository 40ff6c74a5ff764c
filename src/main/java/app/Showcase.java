package app;

import geometries.Cylinder;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Renders the showcase scene into {@code images/showcase.png} and prints the render statistics. */
public final class Showcase {
    private Showcase() {}

    /**
     * Renders the showcase at 800 x 500 with 9 jittered samples per pixel.
     *
     * @param args ignored
     */
    public static void main(String[] args) {
        Camera camera = camera(scene(), 800, 500)
                .setSamplingConfig(new SamplingConfig(9, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .build();
        camera.renderImage();
        System.out.println("wrote " + camera.writeToImage("showcase"));
        System.out.print(camera.getLastStatistics().format());
    }

    /**
     * The showcase view of {@code scene} at the given resolution (16:10).
     *
     * @param scene the scene to view
     * @param width image width in pixels
     * @param height image height in pixels
     * @return a camera builder with location, direction, view plane, resolution and ray tracer set
     */
    public static Camera.Builder camera(Scene scene, int width, int height) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -420, 160))
                .setDirection(new Point(0, 0, 40), Vector.AXIS_Z)
                .setVpDistance(400)
                .setVpSize(320, 200)
                .setResolution(width, height)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    /**
     * Glass and mirror spheres, a capped cylinder, a mirror wall and a triangle on a floor, under soft lights.
     *
     * @return a new showcase scene with soft lights and a clear floor reflection
     */
    public static Scene scene() {
        return scene(true, 0);
    }

    /**
     * The showcase scene with its lights soft (radius and 16 samples) or hard, and the floor's roughness (0 is a
     * clear reflection, larger values a glossy one).
     *
     * @param softLights true for disk lights of 16 samples, false for point lights
     * @param floorRoughness the floor's roughness, at least 0
     * @return a new showcase scene
     */
    public static Scene scene(boolean softLights, double floorRoughness) {
        Scene scene = new Scene("showcase")
                .setBackground(new Color(12, 14, 28))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.06));
        Material floor = new Material()
                .setKd(0.5)
                .setKs(0.2)
                .setShininess(40)
                .setKr(0.15)
                .setRoughness(floorRoughness);
        scene.geometries.add(new Plane(new Point(0, 0, 0), Vector.AXIS_Z)
                .setEmission(new Color(30, 30, 36))
                .setMaterial(floor));
        scene.geometries.add(
                new Sphere(new Point(-70, 40, 45), 45)
                        .setEmission(new Color(10, 20, 40))
                        .setMaterial(new Material()
                                .setKd(0.05)
                                .setKs(0.6)
                                .setShininess(300)
                                .setKt(0.85)
                                .setIndexOfRefraction(1.5)),
                new Sphere(new Point(70, 60, 50), 50)
                        .setEmission(new Color(20, 10, 10))
                        .setMaterial(new Material()
                                .setKd(0.1)
                                .setKs(0.8)
                                .setShininess(500)
                                .setKr(0.8)),
                new Sphere(new Point(0, -40, 20), 20)
                        .setEmission(new Color(120, 30, 20))
                        .setMaterial(new Material().setKd(0.7).setKs(0.4).setShininess(60)),
                new Cylinder(16, new Ray(new Point(-140, 120, 0), Vector.AXIS_Z), 110)
                        .setEmission(new Color(20, 60, 30))
                        .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(30)),
                new Polygon(
                                new Point(-220, 220, 0),
                                new Point(220, 220, 0),
                                new Point(220, 230, 180),
                                new Point(-220, 230, 180))
                        .setEmission(new Color(15, 15, 25))
                        .setMaterial(new Material().setKd(0.3).setKr(0.5)),
                new Triangle(new Point(120, -60, 0), new Point(170, -40, 0), new Point(145, -50, 70))
                        .setEmission(new Color(80, 70, 10))
                        .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(20)));
        scene.lights.add(new PointLight(new Color(260, 230, 190), new Point(-120, -160, 260))
                .setKl(0.0008)
                .setKq(0.000002)
                .setRadius(softLights ? 25 : 0)
                .setNumSamples(16));
        scene.lights.add(new SpotLight(new Color(220, 260, 340), new Point(200, -200, 300), new Vector(-1, 1, -1.5))
                .setNarrowBeam(4)
                .setKl(0.0005)
                .setRadius(softLights ? 10 : 0)
                .setNumSamples(16));
        scene.lights.add(new DirectionalLight(new Color(25, 25, 40), new Vector(0.3, 1, -1)));
        return scene;
    }
}
