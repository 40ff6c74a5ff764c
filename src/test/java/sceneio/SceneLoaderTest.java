package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Mesh;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.Tube;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Color;
import primitives.Double3;
import primitives.Point;
import renderer.Camera;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/** Scene files become the core objects they describe, with the documented defaults. */
class SceneLoaderTest {
    static final Path EVERY_TYPE = Path.of("src/test/resources/sceneio/every-type.json");

    /** The scene files shipped in scenes/. */
    static List<Path> shippedScenes() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            return files.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        }
    }

    @Test
    void everyShippedSceneLoadsWithoutWarnings() throws Exception {
        List<Path> scenes = shippedScenes();
        assertTrue(scenes.size() >= 4, "showcase, soft shadows, AA edges, glass and mirror: " + scenes);
        for (Path file : scenes) {
            LoadedScene loaded = SceneLoader.load(file);
            assertTrue(loaded.warnings().isEmpty(), file + ": " + loaded.warnings());
            assertFalse(loaded.scene().geometries.isEmpty(), file.toString());
        }
    }

    @Test
    void showcaseFileMatchesTheJavaShowcase() throws Exception {
        LoadedScene loaded = SceneLoader.load(Path.of("scenes/showcase.json"));
        Scene java = app.Showcase.scene();
        Scene file = loaded.scene();
        assertEquals(java.background, file.background);
        assertEquals(java.ambientLight.getIntensity(), file.ambientLight.getIntensity());
        assertEquals(java.lights.size(), file.lights.size());
        assertEquals(
                java.geometries.getMembers().size(),
                file.geometries.getMembers().size());
        for (int i = 0; i < java.geometries.getMembers().size(); i++) {
            assertEquals(
                    java.geometries.getMembers().get(i).getClass(),
                    file.geometries.getMembers().get(i).getClass(),
                    "geometry " + i);
        }
        Sphere glass = (Sphere) file.geometries.getMembers().get(1);
        assertEquals(new Point(-70, 40, 45), glass.getCenter());
        assertEquals(1.5, glass.getMaterial().getIndexOfRefraction());
        assertEquals(new Double3(0.85), glass.getMaterial().getKt());
        assertEquals(800, loaded.camera().getNx());
        assertEquals(500, loaded.camera().getNy());
        assertEquals(9, loaded.camera().getSamplingConfig().getSampleCount());
    }

    @Test
    void everyFieldReachesTheCore() throws Exception {
        LoadedScene loaded = SceneLoader.load(EVERY_TYPE);
        Scene scene = loaded.scene();
        assertEquals("every-type", scene.getName());
        assertEquals(-123456789012L, scene.getSeed());
        assertEquals(new Color(1.5, 2, 3), scene.background);
        assertEquals(new Color(25.5, 50, 72), scene.ambientLight.getIntensity());

        PointLight point = assertInstanceOf(PointLight.class, scene.lights.get(0));
        assertEquals(0.5, point.getKc());
        assertEquals(2, point.getRadius());
        assertEquals(4, point.getNumSamples());
        SpotLight spot = assertInstanceOf(SpotLight.class, scene.lights.get(1));
        assertEquals(3.5, spot.getNarrowBeam());
        assertInstanceOf(DirectionalLight.class, scene.lights.get(2));

        var members = scene.geometries.getMembers();
        Plane plane = assertInstanceOf(Plane.class, members.get(0));
        assertEquals(new Double3(0.1, 0.2, 0.3), plane.getMaterial().getKd());
        assertEquals(7, plane.getMaterial().getShininess());
        assertEquals(0.01, plane.getMaterial().getRoughness());
        assertEquals(new Color(1, 2, 3), plane.getEmission());
        Sphere sphere = assertInstanceOf(Sphere.class, members.get(1));
        assertEquals(new Double3(1), sphere.getMaterial().getKd());
        assertInstanceOf(Triangle.class, members.get(2));
        Polygon polygon = assertInstanceOf(Polygon.class, members.get(3));
        assertEquals(5, polygon.getVertices().size());
        assertEquals(new Double3(0.1, 0, 0), polygon.getMaterial().getKr());
        assertInstanceOf(Tube.class, members.get(4));
        Cylinder cylinder = assertInstanceOf(Cylinder.class, members.get(5));
        assertEquals(3, cylinder.getHeight());
        Mesh mesh = assertInstanceOf(Mesh.class, members.get(6));
        assertEquals(2, mesh.triangleCount());
        assertEquals(new Point(2, 12, 0), mesh.vertex(2)); // scaled by 2, moved by (0, 10, 0)
        assertEquals(plane.getMaterial(), mesh.getMaterial(), "a named material is shared");
        Geometries group = assertInstanceOf(Geometries.class, members.get(7));
        assertEquals(2, group.getMembers().size());

        Camera camera = loaded.camera();
        assertEquals(32, camera.getNx());
        assertEquals(2, camera.getThreads());
        assertFalse(camera.getRenderSettings().useBvh());
        assertEquals(3, camera.getRenderSettings().maxLevel());
        assertEquals(SamplingPattern.RANDOM, camera.getRenderSettings().shadowPattern());
        assertTrue(camera.getRenderSettings().adaptiveShadows());
        assertEquals(4, camera.getRenderSettings().glossySampling().getSampleCount());
        assertEquals(TargetShape.CIRCLE, camera.getSamplingConfig().getShape());
        assertEquals(SamplingPattern.HALTON, camera.getSamplingConfig().getPattern());
        assertEquals(4.5, camera.getSamplingConfig().getAdaptiveThreshold());

        assertEquals(8, mesh.getTexCoords().length, "the OBJ's vt reach the mesh");
        // The OBJ's unsupported statements are reported once per kind, naming the file beside the scene; its
        // mtllib (a missing file) is not read, since the scene's material overrides the OBJ's.
        assertEquals(2, loaded.warnings().size(), loaded.warnings().toString());
        assertTrue(loaded.warnings().get(0).startsWith("src/test/resources/sceneio/quad-with-extras.obj: skipped 1"));
    }

    @Test
    void minimalSceneGetsTheDocumentedDefaults(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("tiny scene.json"), """
                {"camera": {"location": [0, 0, 10], "direction": [0, 0, -1], "vpDistance": 10, "vpWidth": 4,
                            "vpHeight": 4},
                 "render": {"width": 8, "height": 8}}
                """);
        LoadedScene loaded = SceneLoader.load(file);
        assertEquals("tiny scene", loaded.scene().getName(), "the file name when the file gives none");
        assertEquals(Color.BLACK, loaded.scene().background);
        assertTrue(loaded.scene().lights.isEmpty());
        assertEquals(new Scene("x").getSeed(), loaded.scene().getSeed());
        assertEquals(Runtime.getRuntime().availableProcessors(), loaded.camera().getThreads());
        assertTrue(loaded.camera().getRenderSettings().useBvh());
        assertEquals(1, loaded.camera().getSamplingConfig().getSampleCount());
        // It renders: the background everywhere.
        loaded.camera().renderImage();
        assertEquals(Color.BLACK, loaded.camera().getImage().getPixel(3, 3));
    }

    @Test
    void theAnnotatedExampleInTheDocsLoads() throws Exception {
        String doc = Files.readString(Path.of("docs/SCENE-FORMAT.md"));
        int start = doc.indexOf("```jsonc\n") + "```jsonc\n".length();
        String example = doc.substring(start, doc.indexOf("```", start));
        LoadedScene loaded = SceneLoader.load(example, "docs/SCENE-FORMAT.md", Path.of("scenes"));
        assertEquals("demo", loaded.scene().getName());
        assertEquals(8, loaded.scene().geometries.getMembers().size());
        assertEquals(3, loaded.scene().lights.size());
    }

    @Test
    void enumsAreReadInAnyCaseAndCommentsAreAllowed() throws Exception {
        LoadedScene loaded = SceneLoader.load("""
                // a comment
                {"camera": {"location": [0, 0, 10], "lookAt": [0, 0, 0], "up": [0, 1, 0], "vpDistance": 1,
                            "vpWidth": 1, "vpHeight": 1}, /* another */
                 "render": {"width": 1, "height": 1, "antiAliasing": {"samples": 4, "pattern": "GRID",
                            "shape": "Circle"}}}
                """, "inline.json", Path.of("."));
        assertEquals(SamplingPattern.GRID, loaded.camera().getSamplingConfig().getPattern());
        assertEquals(TargetShape.CIRCLE, loaded.camera().getSamplingConfig().getShape());
    }
}
