package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Bad MTL files, textures and material references of scene files: each is one {@link SceneFileException} naming
 * the scene file's place and the file and line at fault, never a crash while rendering.
 */
class TextureBadInputTest {
    @TempDir
    Path dir;

    private Path models;

    private SceneFileException error(String meshExtras, String materials) throws Exception {
        Files.writeString(dir.resolve("scene.json"), TexturedSceneTest.scene(meshExtras, materials));
        return assertThrows(SceneFileException.class, () -> SceneLoader.load(dir.resolve("scene.json")));
    }

    private SceneFileException errorWithMtl(String mtl) throws Exception {
        Files.writeString(models.resolve("board.mtl"), mtl);
        return error("", "");
    }

    private void setUp() throws Exception {
        TexturedSceneTest.writeModel(dir);
        models = dir.resolve("models");
    }

    private static void assertMessage(SceneFileException e, String... parts) {
        for (String part : parts) assertTrue(e.getMessage().contains(part), e.getMessage() + "\n lacks: " + part);
    }

    @Test
    void aMissingOrBadMtlFileNamesTheObjLineAndTheMtlLine() throws Exception {
        setUp();
        Files.delete(models.resolve("board.mtl"));
        SceneFileException e = error("", "");
        assertEquals("$.geometries[0].file", e.getJsonPath());
        assertMessage(
                e, "OBJ file " + dir.resolve("models/board.obj") + ":1: mtllib: MTL file \"board.mtl\" not found");
        e = errorWithMtl(TexturedSceneTest.MTL.replace("Kd 1 0 0", "Kd 1 0"));
        assertMessage(e, "board.obj:1: mtllib: MTL file ", "board.mtl:3: 'Kd' needs r g b");
    }

    @Test
    void anUndefinedMaterialListsTheDefinedOnes() throws Exception {
        setUp();
        SceneFileException e = errorWithMtl(TexturedSceneTest.MTL.replace("newmtl red", "newmtl crimson"));
        assertMessage(
                e,
                "board.obj uses material \"red\" (usemtl), which none of its material libraries defines; they define:"
                        + " \"crimson\", \"tex\"; define it there or give it in the mesh's \"materials\"");
    }

    @Test
    void overridingAMaterialTheObjDoesNotUseIsAnError() throws Exception {
        setUp();
        SceneFileException e = error(", \"materials\": {\"blue\": {\"kD\": 1}}", "");
        assertEquals("$.geometries[0].materials.blue", e.getJsonPath());
        assertMessage(e, "the OBJ file uses no material \"blue\"; its materials (usemtl) are: \"red\", \"tex\"");
        assertTrue(e.getLine() > 0, "the place in the scene file");
    }

    @Test
    void missingUnreadableAndForeignTexturesAreNamed() throws Exception {
        setUp();
        Files.delete(models.resolve("tex.png"));
        assertMessage(error("", ""), "board.mtl:7: map_Kd: texture \"", "tex.png\" not found");
        Files.writeString(models.resolve("tex.png"), "this is text, not an image");
        assertMessage(error("", ""), "board.mtl:7: map_Kd: texture \"", "tex.png\" is not a PNG or JPEG image");
        BufferedImage small = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        ImageIO.write(small, "gif", models.resolve("tex.png").toFile());
        assertMessage(error("", ""), "is not a PNG or JPEG image");
        ImageIO.write(small, "png", models.resolve("tex.png").toFile());
        byte[] png = Files.readAllBytes(models.resolve("tex.png"));
        Files.write(models.resolve("tex.png"), Arrays.copyOf(png, 40)); // the header, but not the pixels
        assertMessage(error("", ""), "tex.png\" cannot be read as a PNG or JPEG image");
        Files.createDirectory(models.resolve("folder.png"));
        assertMessage(
                errorWithMtl(TexturedSceneTest.MTL.replace("tex.png", "folder.png")),
                "folder.png\" is not a regular file");
    }

    @Test
    void tooLargeTexturesAreRefusedFromTheirHeader() throws Exception {
        setUp();
        ImageIO.write(
                new BufferedImage(16_385, 1, BufferedImage.TYPE_BYTE_GRAY),
                "png",
                models.resolve("tex.png").toFile());
        assertMessage(
                error("", ""),
                "tex.png\" is 16385 x 1 pixels; a texture may have at most 16,384 on a side and 16,777,216 in all");
    }

    @Test
    void texturesOutsideTheSceneFolderAreNotLookedAt() throws Exception {
        setUp();
        SceneFileException e = errorWithMtl(TexturedSceneTest.MTL.replace("tex.png", "../../secret.png"));
        assertMessage(e, "board.mtl:7: map_Kd: ", "leads outside the scene file's folder");
        e = errorWithMtl(TexturedSceneTest.MTL.replace("tex.png", "/etc/passwd"));
        assertMessage(e, "board.mtl:7: map_Kd: ", "must be a path relative to the scene file's folder");
        Files.writeString(models.resolve("board.obj"), TexturedSceneTest.BOARD.replace("board.mtl", "../../x.mtl"));
        assertMessage(error("", ""), "board.obj:1: mtllib: ", "leads outside the scene file's folder");
    }

    @Test
    void sceneTextureErrorsPointAtTheField() throws Exception {
        setUp();
        String missing = "\"t\": {\"kDMap\": {\"file\": \"models/none.png\"}}";
        SceneFileException e = error(", \"material\": \"t\"", missing);
        assertEquals("$.materials.t.kDMap.file", e.getJsonPath());
        assertMessage(e, "texture \"", "none.png\" not found");
        e = error(", \"material\": \"t\"", "\"t\": {\"kDMap\": {\"file\": \"models/tex.png\", \"wrap\": \"spiral\"}}");
        assertMessage(e, "spiral");
        e = error(", \"material\": \"t\"", "\"t\": {\"kDMap\": {\"wrap\": \"clamp\"}}");
        assertEquals("$.materials.t.kDMap", e.getJsonPath());
        assertMessage(e, "missing required field \"file\"");
    }

    @Test
    void aBadTextureIndexNamesTheObjLine() throws Exception {
        setUp();
        Files.writeString(models.resolve("board.obj"), TexturedSceneTest.BOARD.replace("6/3", "6/9"));
        SceneFileException e = error("", "");
        assertMessage(e, "board.obj:15: face corner '6/9': texture coordinate index 9 is out of range");
        assertFalse(e.getMessage().contains("Exception"), e.getMessage());
    }
}
