package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Instance;
import geometries.Intersectable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Point;
import primitives.Transform;

/** Prototypes and instances in scene files: placement, sharing, writing back, and every mistake named. */
class SceneInstancesTest {
    private static final Path RESOURCES = Path.of("src/test/resources/sceneio");

    private static final String SCENE = """
            {
              "camera": {"location": [0, -10, 0], "lookAt": [0, 0, 0], "vpDistance": 10, "vpWidth": 4,
                         "vpHeight": 4},
              "render": {"width": 4, "height": 4},
              "prototypes": {
                "post": {"type": "group", "geometries": [
                  {"type": "sphere", "center": [0, 0, 1], "radius": 0.5, "material": {"kD": 0.3}},
                  {"type": "cylinder", "radius": 0.1, "axis": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
                   "height": 1}
                ]}
              },
              "geometries": [
                {"type": "instance", "of": "post", "translate": [2, 0, 0]},
                {"type": "instance", "of": "post", "scale": [1, 1, 2], "rotate": {"axis": [1, 0, 0], "degrees": 90},
                 "translate": [-2, 0, 0]},
                {"type": "instance", "of": "post", "matrix": [1, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1, 0]}
              ]
            }
            """;

    private static SceneFileException error(String json) {
        return assertThrows(SceneFileException.class, () -> SceneLoader.load(json, "bad.json", RESOURCES));
    }

    @Test
    void instancesShareOnePrototypeAndApplyScaleRotateTranslateInOrder() throws SceneFileException {
        LoadedScene loaded = SceneLoader.load(SCENE, "ok.json", RESOURCES);
        assertTrue(loaded.warnings().isEmpty(), loaded.warnings().toString());
        List<Intersectable> members = loaded.scene().geometries.getMembers();
        assertEquals(3, members.size());
        Instance a = assertInstanceOf(Instance.class, members.get(0));
        Instance b = assertInstanceOf(Instance.class, members.get(1));
        Instance c = assertInstanceOf(Instance.class, members.get(2));
        assertSame(a.prototype(), b.prototype());
        assertSame(a.prototype(), c.prototype());
        assertEquals(Transform.translate(2, 0, 0), a.transform());
        // (0, 0, 1) is stretched to (0, 0, 2), turned about x to (0, -2, 0), moved to (-2, -2, 0)
        Point top = b.transform().apply(new Point(0, 0, 1));
        assertEquals(0, top.distance(new Point(-2, -2, 0)), 1e-12, top.toString());
        assertEquals(new Point(0, 3, 1), c.transform().apply(new Point(0, 0, 1)));
    }

    @Test
    void writingBackKeepsThePrototypesAndPlacements(@TempDir Path dir) throws Exception {
        LoadedScene loaded = SceneLoader.load(SCENE, "ok.json", RESOURCES);
        Path file = dir.resolve("copy.json");
        SceneExporter.export(loaded.scene(), loaded.camera(), file);
        String json = Files.readString(file);
        assertTrue(json.contains("\"prototypes\""), json);
        LoadedScene again = SceneLoader.load(json, "copy.json", dir);
        List<Intersectable> members = again.scene().geometries.getMembers();
        assertEquals(3, members.size());
        for (int i = 0; i < 3; i++) {
            Instance was = (Instance) loaded.scene().geometries.getMembers().get(i);
            Instance is = (Instance) members.get(i);
            assertEquals(was.transform(), is.transform(), "instance " + i);
            assertSame(((Instance) members.get(0)).prototype(), is.prototype());
        }
        assertTrue(json.contains("\"translate\" : [ 2, 0, 0 ]"), "a pure move is written as a translation: " + json);
    }

    @Test
    void mistakesAreNamedWithTheirPlace() {
        assertEquals(
                "bad.json:13:26: $.geometries[0].of: unknown prototype \"pots\"; defined in \"prototypes\": post",
                error(SCENE.replace("\"of\": \"post\", \"translate\": [2", "\"of\": \"pots\", \"translate\": [2"))
                        .getMessage());
        assertTrue(error(SCENE.replace("\"matrix\": [1, 0, 0, 0,", "\"matrix\": [1, 0, 0,"))
                .getMessage()
                .contains("$.geometries[2].matrix: a matrix is 12 numbers"));
        assertTrue(error(SCENE.replace("\"matrix\": [", "\"translate\": [1, 1, 1], \"matrix\": ["))
                .getMessage()
                .contains("give either \"matrix\" or \"scale\", \"rotate\" and \"translate\", not both"));
        assertTrue(error(SCENE.replace("\"scale\": [1, 1, 2]", "\"scale\": [1, 0, 2]"))
                .getMessage()
                .contains("$.geometries[1].scale: a scale must be non-zero on every axis"));
        assertTrue(error(SCENE.replace("\"degrees\": 90", "\"angle\": 90"))
                .getMessage()
                .contains("unknown field \"angle\""));
        assertTrue(error(SCENE.replace("{\"axis\": [1, 0, 0], \"degrees\": 90}", "{\"axis\": [1, 0, 0]}"))
                .getMessage()
                .contains("a rotation needs \"axis\""));
        assertTrue(error(SCENE.replace(
                        "\"matrix\": [1, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1, 0]",
                        "\"matrix\": [1, 0, 0, 0, 2, 0, 0, 3, 0, 0, 1, 0]"))
                .getMessage()
                .contains("must be invertible"));
        String unbounded = SCENE.replace(
                "{\"type\": \"sphere\", \"center\": [0, 0, 1]",
                "{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 0, 1]}, {\"type\": \"sphere\", \"center\": [0, 0, 1]");
        assertTrue(error(unbounded).getMessage().contains("$.prototypes.post: prototype 'post' is unbounded"));
        String nested = SCENE.replace(
                "{\"type\": \"sphere\", \"center\": [0, 0, 1]",
                "{\"type\": \"instance\", \"of\": \"post\"}, {\"type\": \"sphere\", \"center\": [0, 0, 1]");
        assertTrue(
                error(nested).getMessage().contains("unknown prototype \"post\"; defined in \"prototypes\": none"),
                "a prototype cannot place itself or one defined later");
    }

    @Test
    void aPrototypeNeverPlacedIsAWarning() throws SceneFileException {
        String unused = SCENE.replace(
                "\"prototypes\": {",
                "\"prototypes\": {\"spare\": {\"type\": \"sphere\"," + " \"center\": [0, 0, 0], \"radius\": 1},");
        assertEquals(
                List.of("prototype \"spare\" is defined but never placed"),
                SceneLoader.load(unused, "ok.json", RESOURCES).warnings());
    }
}
