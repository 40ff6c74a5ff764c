package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Geometries;
import geometries.Mesh;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Color;
import primitives.Texture;
import renderer.Camera;
import renderer.ImageWriter;

/**
 * Renders scene files with OBJ meshes whose materials come from MTL files and textures, and checks the image: the
 * per-material colours and the texture's texels appear where they belong, overrides apply, textures are loaded
 * once, and the image is bit-identical for any thread count and with the BVH off.
 */
class TexturedSceneTest {
    /**
     * Two unit-high quads facing +z: the left one (x -2..0) material "red", the right one (x 0..2) material "tex"
     * whose texture coordinates span the 2 x 1 texture (white, blue) left to right.
     */
    static final String BOARD = """
            mtllib board.mtl
            v -2 -1 0
            v 0 -1 0
            v 0 1 0
            v -2 1 0
            v 2 -1 0
            v 2 1 0
            vt 0 0
            vt 1 0
            vt 1 1
            vt 0 1
            usemtl red
            f 1 2 3 4
            usemtl tex
            f 2/1 5/2 6/3 3/4
            """;

    static final String MTL = """
            newmtl red
            Ka 0 0 0
            Kd 1 0 0
            newmtl tex
            Ka 0 0 0
            Kd 1 1 1
            map_Kd -clamp on tex.png
            """;

    /** The camera looks straight down at the board; a light straight down makes the shading kD times 255. */
    static String scene(String meshExtras, String materials) {
        return """
                {"camera": {"location": [0, 0, 10], "lookAt": [0, 0, 0], "up": [0, 1, 0], "vpDistance": 10,
                            "vpWidth": 4, "vpHeight": 2},
                 "render": {"width": 40, "height": 20, "threads": 1},
                 "materials": {%s},
                 "lights": [{"type": "directional", "color": [255, 255, 255], "direction": [0, 0, -1]}],
                 "geometries": [{"type": "mesh", "file": "models/board.obj"%s}]}
                """.formatted(materials, meshExtras);
    }

    static void writeModel(Path dir) throws Exception {
        Path models = Files.createDirectories(dir.resolve("models"));
        Files.writeString(models.resolve("board.obj"), BOARD);
        Files.writeString(models.resolve("board.mtl"), MTL);
        BufferedImage texture = new BufferedImage(2, 1, BufferedImage.TYPE_INT_RGB);
        texture.setRGB(0, 0, 0xFFFFFF);
        texture.setRGB(1, 0, 0x0000FF);
        ImageIO.write(texture, "png", models.resolve("tex.png").toFile());
    }

    private static ImageWriter render(Path dir, String json) throws Exception {
        Path file = dir.resolve("scene.json");
        Files.writeString(file, json);
        return SceneLoader.load(file).camera().renderImage().getImage();
    }

    private static void assertColor(Color expected, Color actual, String where) {
        assertEquals(expected.getR(), actual.getR(), 1e-9, where + " " + actual);
        assertEquals(expected.getG(), actual.getG(), 1e-9, where + " " + actual);
        assertEquals(expected.getB(), actual.getB(), 1e-9, where + " " + actual);
    }

    @Test
    void mtlColoursAndTexelsAppearWhereTheyBelong(@TempDir Path dir) throws Exception {
        writeModel(dir);
        ImageWriter image = render(dir, scene("", ""));
        // Pixel columns 0..19 see x -2..0 (red), 20..39 see x 0..2: the texture, white then blue.
        for (int y = 2; y < 18; y += 5) {
            for (int x = 1; x < 19; x += 3) assertColor(new Color(255, 0, 0), image.getPixel(x, y), "red at " + x);
            // With clamp, the outer quarters of the quad show one texel each exactly.
            for (int x = 21; x < 24; x++) assertColor(new Color(255, 255, 255), image.getPixel(x, y), "white " + x);
            for (int x = 36; x < 39; x++) assertColor(new Color(0, 0, 255), image.getPixel(x, y), "blue " + x);
            // Between the texel centres (u 0.25..0.75) the colour blends linearly from white to blue.
            Color middle = image.getPixel(29, y);
            assertTrue(middle.getR() > 100 && middle.getR() < 155 && middle.getB() == 255, middle.toString());
        }
    }

    @Test
    void theSceneFileOverridesSingleMaterialsOrAll(@TempDir Path dir) throws Exception {
        writeModel(dir);
        ImageWriter one = render(
                dir, scene(", \"materials\": {\"red\": \"green\"}", "\"green\": {\"kA\": 0, \"kD\": [0, 1, 0]}"));
        assertColor(new Color(0, 255, 0), one.getPixel(5, 10), "overridden red");
        assertColor(new Color(0, 0, 255), one.getPixel(37, 10), "the texture stays");
        ImageWriter all = render(dir, scene(", \"material\": {\"kA\": 0, \"kD\": 0.5}", ""));
        assertColor(new Color(127.5, 127.5, 127.5), all.getPixel(5, 10), "one material for all");
        assertColor(new Color(127.5, 127.5, 127.5), all.getPixel(37, 10), "one material for all");
    }

    @Test
    void aSceneMaterialTakesATextureAndTexturesAreLoadedOnce(@TempDir Path dir) throws Exception {
        writeModel(dir);
        String materials =
                "\"t\": {\"kA\": 0, \"kD\": 0.5, \"kDMap\": {\"file\": \"models/tex.png\", \"wrap\": \"clamp\"}}";
        Path file = dir.resolve("scene.json");
        Files.writeString(file, scene(", \"materials\": {\"red\": \"t\"}", materials));
        LoadedScene loaded = SceneLoader.load(file);
        Geometries group = assertInstanceOf(
                Geometries.class, loaded.scene().geometries.getMembers().get(0));
        Mesh left = assertInstanceOf(Mesh.class, group.getMembers().get(0));
        Mesh right = assertInstanceOf(Mesh.class, group.getMembers().get(1));
        // Both materials use tex.png with clamp: one texture.
        assertSame(left.getMaterial().getKdMap(), right.getMaterial().getKdMap());
        assertEquals(Texture.Wrap.CLAMP, left.getMaterial().getKdMap().getWrap());
        ImageWriter image = loaded.camera().renderImage().getImage();
        // The left quad has no texture coordinates: it shows the texel at (0, 0), white, times kD 0.5.
        assertColor(new Color(127.5, 127.5, 127.5), image.getPixel(5, 10), "untextured mesh, textured material");
        assertTrue(
                loaded.warnings()
                        .get(0)
                        .endsWith("board.obj: the faces of material \"red\" have a textured material"
                                + " (kDMap, map_Kd) but no texture coordinates (vt): the texture shows one colour"),
                loaded.warnings().toString());
        assertEquals(1, loaded.warnings().size(), loaded.warnings().toString());
    }

    @Test
    void aTexturedSphereIsWarnedAbout(@TempDir Path dir) throws Exception {
        String json = """
                {"camera": {"location": [0, 0, 10], "lookAt": [0, 0, 0], "up": [0, 1, 0], "vpDistance": 10,
                            "vpWidth": 4, "vpHeight": 2},
                 "render": {"width": 4, "height": 2},
                 "geometries": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                 "material": {"kDMap": {"file": "models/tex.png"}}}]}
                """;
        writeModel(dir);
        Path file = Files.writeString(dir.resolve("sphere.json"), json);
        assertEquals(
                java.util.List.of(file + ": $.geometries[0]: a sphere has no texture coordinates (only OBJ meshes with"
                        + " vt have them): its texture (kDMap) shows one colour"),
                SceneLoader.load(file).warnings());
    }

    @Test
    void materialsWithTexturesAndOverridesRoundTrip() throws Exception {
        sceneio.model.SceneDocument d = SceneLoader.read(Path.of("scenes/textured-model.json"));
        assertEquals(d, SceneLoader.parse(SceneWriter.toJson(d), "again.json"));
        String json = SceneWriter.toJson(d);
        assertTrue(json.contains("\"kDMap\""), json);
        assertTrue(json.contains("\"wrap\" : \"mirror\"") || json.contains("\"wrap\":\"mirror\""), json);
    }

    @Test
    void imagesAreBitIdenticalForAnyThreadCountAndWithoutTheBvh(@TempDir Path dir) throws Exception {
        writeModel(dir);
        String base = scene("", "")
                .replace(
                        "\"height\": 20, \"threads\": 1",
                        "\"height\": 20, \"threads\": 1," + " \"antiAliasing\": {\"samples\": 4}");
        ImageWriter reference = render(dir, base);
        for (String variant : new String[] {"\"threads\": 2", "\"threads\": 2, \"bvh\": false"}) {
            ImageWriter other = render(dir, base.replace("\"threads\": 1", variant));
            for (int y = 0; y < 20; y++) {
                for (int x = 0; x < 40; x++) {
                    assertEquals(reference.getPixel(x, y), other.getPixel(x, y), variant + " at " + x + ", " + y);
                }
            }
        }
    }

    @Test
    void theShowcaseSceneLoadsWithoutWarnings() throws Exception {
        LoadedScene loaded = SceneLoader.load(Path.of("scenes/textured-model.json"));
        assertTrue(loaded.warnings().isEmpty(), loaded.warnings().toString());
        // What must travel with the scene file (the Spark bundle ships these), each once.
        assertEquals(
                java.util.List.of(
                        "models/crate/crate.obj",
                        "models/crate/crate.mtl",
                        "models/crate/planks.png",
                        "models/crate/tiles.png",
                        "models/crate/floor.obj"),
                loaded.files());
        Camera camera = loaded.camera();
        assertEquals(480, camera.getNx());
    }
}
