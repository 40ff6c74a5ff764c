package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import sceneio.model.AmbientDocument;
import sceneio.model.CameraDocument;
import sceneio.model.Coefficient;
import sceneio.model.MaterialDocument;
import sceneio.model.MaterialRef;
import sceneio.model.RenderDocument;
import sceneio.model.SamplingDocument;
import sceneio.model.SceneDocument;
import sceneio.model.SphereDocument;
import sceneio.model.Vec3;

/** Writing a document and reading it back gives an equal document, and a second write gives the same text. */
class SceneRoundTripTest {
    static List<Path> files() throws Exception {
        List<Path> files = new ArrayList<>(SceneLoaderTest.shippedScenes());
        files.add(SceneLoaderTest.EVERY_TYPE);
        return files;
    }

    @ParameterizedTest
    @MethodSource("files")
    void fileRoundTrips(Path file) throws Exception {
        SceneDocument read = SceneLoader.read(file);
        String written = SceneWriter.toJson(read);
        SceneDocument reread = SceneLoader.parse(written, "written " + file);
        assertEquals(read, reread);
        assertEquals(written, SceneWriter.toJson(reread), "writing is deterministic");
    }

    @Test
    void writtenFileLoadsToTheSameSceneAndOmitsAbsentFields(@TempDir Path dir) throws Exception {
        SceneDocument read = SceneLoader.read(SceneLoaderTest.EVERY_TYPE);
        // Beside the OBJ it refers to, so the relative path still resolves.
        Path copy = SceneLoaderTest.EVERY_TYPE.resolveSibling("written-every-type.json");
        try {
            SceneWriter.write(read, copy);
            LoadedScene loaded = SceneLoader.load(copy);
            assertEquals(read, loaded.document());
            assertEquals(
                    SceneLoader.load(SceneLoaderTest.EVERY_TYPE).scene().getSeed(),
                    loaded.scene().getSeed());
        } finally {
            Files.deleteIfExists(copy);
        }
        SceneDocument sparse = new SceneDocument(null, "sparse", null, null, null, null, null, null, null, null);
        String json = SceneWriter.toJson(sparse);
        assertEquals("{\n  \"name\" : \"sparse\"\n}\n", json);
    }

    @Test
    void documentBuiltInJavaRoundTripsWithExactDoubles() throws Exception {
        double awkward = 0.1 + 0.2; // 0.30000000000000004: must survive the text form exactly
        SceneDocument d = new SceneDocument(
                1,
                "java",
                Long.MIN_VALUE,
                new Vec3(-0.0, 1e-300, 1e300),
                new AmbientDocument(new Vec3(1, 2, 3), new Coefficient(awkward, 0.5, 0.5)),
                new CameraDocument(
                        new Vec3(0, 0, 1), null, new Vec3(0, 0, -1), new Vec3(0, 1, 0), awkward, 2.0, 3.0, null),
                new RenderDocument(
                        10,
                        20,
                        new SamplingDocument(9, TargetShape.RECTANGLE, SamplingPattern.GRID, null),
                        null,
                        true,
                        null,
                        null,
                        null,
                        null,
                        0.25),
                Map.of("m", new MaterialDocument(Coefficient.of(awkward), null, null, 3, null, null, null, null)),
                List.of(),
                List.of(
                        new SphereDocument(new Vec3(1, 2, 3), awkward, MaterialRef.named("m"), null),
                        new SphereDocument(
                                new Vec3(1, 2, 3),
                                1.0,
                                MaterialRef.of(new MaterialDocument(null, null, null, null, null, null, 1.5, null)),
                                new Vec3(4, 5, 6))));
        String json = SceneWriter.toJson(d);
        assertEquals(d, SceneLoader.parse(json, "java.json"));
        assertFalse(json.contains("null"), json);
    }
}
