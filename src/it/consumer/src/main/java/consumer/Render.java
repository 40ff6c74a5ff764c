package consumer;

import geometries.Plane;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import scene.Scene;

/** README's embedding example, small: renders with the library's core alone, nothing else on the classpath. */
public final class Render {
    public static void main(String[] args) {
        Scene scene = new Scene("consumer").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.6)),
                new Sphere(new Point(0, 0, 1), 1).setMaterial(new Material().setKd(0.5).setKs(0.5)));
        scene.lights.add(new PointLight(new Color(300, 280, 250), new Point(3, -4, 6)));
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -8, 3))
                .setDirection(new Point(0, 0, 1), Vector.AXIS_Z)
                .setVpDistance(6)
                .setVpSize(4, 3)
                .setResolution(40, 30)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
        camera.renderImage();
        System.out.print(camera.getLastStatistics().format());
    }
}
