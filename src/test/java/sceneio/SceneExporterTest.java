package sceneio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import app.Showcase;
import geometries.Geometries;
import geometries.Intersectable;
import geometries.Mesh;
import geometries.Meshes;
import java.nio.file.Files;
import java.nio.file.Path;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** A scene built in Java, written as a scene file and loaded back, renders the same picture. */
class SceneExporterTest {

    @Test
    void theShowcaseRoundTripsThroughAFile(@TempDir Path dir) throws Exception {
        Scene scene = Showcase.scene();
        Camera camera = Showcase.camera(scene, 64, 40)
                .setSamplingConfig(new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .build();
        Path file = dir.resolve("showcase.json");
        SceneExporter.export(scene, camera, file);
        LoadedScene loaded = SceneLoader.load(file);
        ImageWriter original = camera.renderImage().getImage();
        ImageWriter reloaded = loaded.camera().renderImage().getImage();
        // Directions are normalized once more on loading, which may move them by an ulp: allow a few pixels.
        int differing = 0;
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 64; x++) {
                Color a = original.getPixel(x, y), b = reloaded.getPixel(x, y);
                double d = Math.max(
                        Math.abs(a.getR() - b.getR()),
                        Math.max(Math.abs(a.getG() - b.getG()), Math.abs(a.getB() - b.getB())));
                if (d > 1e-6) differing++;
            }
        }
        assertTrue(differing <= 64 * 40 / 100, differing + " of " + 64 * 40 + " pixels differ");
        assertEquals(scene.lights.size(), loaded.scene().lights.size());
        assertEquals(scene.getSeed(), loaded.scene().getSeed());
        // Written again, the loaded document gives the same text: the export is a valid, stable file.
        assertEquals(
                SceneWriter.toJson(loaded.document()), Files.readString(file).strip() + "\n");
    }

    @Test
    void meshesGoToObjFilesThatReadBackBitForBit(@TempDir Path dir) throws Exception {
        Mesh sphere = Meshes.icosphere(2).transformed(3.3, 0.1, -7.25, 1e-3);
        sphere.setMaterial(new Material().setKd(0.5));
        Scene scene = new Scene("mesh");
        scene.geometries.add(sphere);
        scene.lights.add(new PointLight(new Color(100, 100, 100), new Point(10, 10, 10)));
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -30, 0))
                .setDirection(new Point(0, 0, 0))
                .setVpDistance(10)
                .setVpSize(10, 10)
                .setResolution(8, 8)
                .setRayTracer(new renderer.SimpleRayTracer(scene))
                .build();
        Path file = dir.resolve("mesh.json");
        SceneExporter.export(scene, camera, file);
        assertTrue(Files.exists(dir.resolve("models/mesh/mesh-0.obj")));
        Intersectable only = loadedGeometry(file);
        Mesh back = (Mesh) only;
        assertArrayEquals(sphere.getVertices(), back.getVertices());
        assertArrayEquals(sphere.getIndices(), back.getIndices());
    }

    private static Intersectable loadedGeometry(Path file) throws SceneFileException {
        Geometries g = SceneLoader.load(file).scene().geometries;
        return g.getMembers().get(0);
    }

    @Test
    void lightRangesRoundTrip(@TempDir Path dir) throws SceneFileException {
        Scene scene = new Scene("range");
        scene.lights.add(new PointLight(new Color(1, 1, 1), Point.ZERO).setRange(10));
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -30, 0))
                .setDirection(new Point(0, 0, 0))
                .setVpDistance(10)
                .setVpSize(10, 10)
                .setResolution(8, 8)
                .setRayTracer(new renderer.SimpleRayTracer(scene))
                .build();
        SceneExporter.export(scene, camera, dir.resolve("range.json"));
        PointLight back = (PointLight)
                SceneLoader.load(dir.resolve("range.json")).scene().lights.get(0);
        assertEquals(10, back.getRange());
    }
}
