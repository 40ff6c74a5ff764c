package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Plane;
import geometries.Sphere;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import lighting.AmbientLight;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
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

/** The "embed it in your code" example of README.md, line for line, so it cannot rot. */
class ReadmeExampleTest {
    @Test
    void theReadmeExampleRendersAndWritesItsImage() {
        // --- README example begins
        Scene scene = new Scene("hello").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setMaterial(new Material().setKd(0.6).setKr(0.2)),
                new Sphere(new Point(0, 0, 1), 1)
                        .setEmission(new Color(120, 20, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)));
        scene.lights.add(new PointLight(new Color(300, 280, 250), new Point(3, -4, 6))
                .setRadius(0.5)
                .setNumSamples(16));
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -8, 3))
                .setDirection(new Point(0, 0, 1), Vector.AXIS_Z)
                .setVpDistance(6)
                .setVpSize(4, 3)
                .setResolution(400, 300)
                .setSamplingConfig(new SamplingConfig(9, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
        camera.renderImage().writeToImage("hello"); // images/hello.png
        System.out.print(camera.getLastStatistics().format()); // time, rays by kind, what was simulated
        // --- README example ends
        Path image = Path.of("images", "hello.png");
        assertTrue(Files.exists(image));
        assertEquals(9L * 400 * 300, camera.getLastStatistics().rays().camera);
        // The sphere in the middle is red; the floor under it is grey (lit or ambient), not black.
        Color sphere = camera.getImage().getPixel(200, 150),
                floor = camera.getImage().getPixel(20, 280);
        assertTrue(sphere.getR() > 100 && sphere.getR() > 1.4 * sphere.getG(), sphere.toString());
        assertTrue(floor.getR() > 10 && floor.getB() > 0.7 * floor.getR(), floor.toString());
    }

    @Test
    void theReadmeShowsExactlyThisExample() throws java.io.IOException {
        List<String> source = Files.readAllLines(Path.of("src/test/java/app/ReadmeExampleTest.java"));
        int begin = source.indexOf("        // --- README example begins"),
                end = source.indexOf("        // --- README example ends");
        assertTrue(begin > 0 && end > begin, "markers in the test source");
        String example = source.subList(begin + 1, end).stream()
                .map(line -> line.substring(Math.min(8, line.length())))
                .collect(Collectors.joining("\n"));
        String readme = Files.readString(Path.of("README.md"));
        assertTrue(readme.contains("```java\n" + example + "\n```"), "README.md must show the example of this test");
    }
}
