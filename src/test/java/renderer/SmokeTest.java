package renderer;

import static org.junit.jupiter.api.Assertions.*;

import geometries.*;
import lighting.*;
import org.junit.jupiter.api.Test;
import primitives.*;
import scene.Scene;

class SmokeTest {
    @Test
    void glassAndMirror() {
        Scene scene = new Scene("smoke")
                .setBackground(new Color(20, 20, 40))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Sphere(new Point(0, 0, -50), 50)
                        .setEmission(new Color(0, 0, 100))
                        .setMaterial(new Material()
                                .setKd(0.4)
                                .setKs(0.3)
                                .setShininess(100)
                                .setKt(0.3)),
                new Sphere(new Point(0, 0, -50), 25)
                        .setEmission(new Color(100, 20, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(100)),
                new Triangle(new Point(-150, -150, -115), new Point(150, -150, -135), new Point(75, 75, -150))
                        .setMaterial(new Material().setKr(0.8).setKd(0.1)),
                new Plane(new Point(0, -60, 0), new Vector(0, 1, 0))
                        .setEmission(new Color(40, 40, 40))
                        .setMaterial(new Material().setKd(0.5)));
        scene.lights.add(new SpotLight(new Color(1000, 600, 0), new Point(-100, -100, 500), new Vector(-1, -1, -2))
                .setKl(0.0004)
                .setKq(0.0000006));
        scene.lights.add(new PointLight(new Color(500, 500, 500), new Point(60, 100, 100)).setKl(0.0005));
        Camera cam = Camera.getBuilder()
                .setLocation(new Point(0, 0, 1000))
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpDistance(1000)
                .setVpSize(200, 200)
                .setResolution(400, 400)
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
        cam.renderImage();
        System.out.println(cam.getLastStatistics());
        cam.writeToImage("smoke");
        cam.setBvh(false).renderImage();
        System.out.println(cam.getLastStatistics());
    }
}
