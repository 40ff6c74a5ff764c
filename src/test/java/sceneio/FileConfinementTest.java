package sceneio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * References from a scene file resolve, links followed, inside the scene's folder tree or an allowed one; anything
 * else is refused before the path outside is looked at, so a refusal says the same whether a file exists there or
 * not.
 */
class FileConfinementTest {
    @TempDir
    Path dir;

    private Path scenes, outside;

    @BeforeEach
    void folders() throws IOException {
        scenes = Files.createDirectories(dir.resolve("scenes/models")).getParent();
        outside = Files.createDirectories(dir.resolve("outside"));
        Files.writeString(scenes.resolve("models/a.obj"), "v 0 0 0\n");
        Files.writeString(outside.resolve("secret"), "SECRET\n");
    }

    private Path resolve(String reference, Path... allowed) {
        return new FileConfinement(scenes, List.of(allowed)).resolve("OBJ file", reference);
    }

    private String refused(String reference) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> resolve(reference));
        assertFalse(e.getMessage().contains("SECRET"), e.getMessage());
        return e.getMessage();
    }

    @Test
    void pathsInsideTheTreeResolveToTheirRealPath() throws IOException {
        Path real = scenes.resolve("models/a.obj").toRealPath();
        assertEquals(real, resolve("models/a.obj"));
        assertEquals(real, resolve("./models/../models/a.obj"));
        assertEquals(real, resolve("../scenes/models/a.obj"), "out of the folder and back in by name");
        // A missing file inside is resolved (the loader then says "not found": that reveals nothing).
        assertEquals(scenes.toRealPath().resolve("models/missing.obj"), resolve("models/missing.obj"));
    }

    @Test
    void pathsLeavingTheTreeAreRefusedWithoutLookingOutside() {
        String exists = refused("../outside/secret");
        String missing = refused("../outside/missing");
        assertTrue(exists.contains("leads outside the scene file's folder"), exists);
        // The first name outside is where the walk stopped: the same for a file that exists and one that does not.
        assertEquals(exists, missing.replace("missing", "secret"));
        assertTrue(exists.contains("(to " + dir.toAbsolutePath().normalize().resolve("outside")), exists);
        assertTrue(refused("/etc/passwd").contains("must be a path relative"));
        assertTrue(refused("../../../../../../../../etc/passwd").contains("leads outside"));
    }

    @Test
    void linksAreFollowedAndMayNotLeadOut() throws IOException {
        Path real = scenes.resolve("models/a.obj").toRealPath();
        Files.createSymbolicLink(scenes.resolve("inner.obj"), Path.of("models/a.obj"));
        Files.createSymbolicLink(scenes.resolve("chain.obj"), Path.of("inner.obj"));
        Files.createSymbolicLink(scenes.resolve("absolute.obj"), real);
        assertEquals(real, resolve("inner.obj"));
        assertEquals(real, resolve("chain.obj"));
        assertEquals(real, resolve("absolute.obj"), "an absolute link into the tree");

        Files.createSymbolicLink(scenes.resolve("out.obj"), outside.resolve("secret"));
        Files.createSymbolicLink(scenes.resolve("dangling.obj"), outside.resolve("missing"));
        Files.createSymbolicLink(scenes.resolve("models/up"), Path.of("../../outside"));
        String viaLink = refused("out.obj");
        assertTrue(viaLink.contains("leads outside"), viaLink);
        assertEquals(viaLink.replace("out.obj", "dangling.obj"), refused("dangling.obj"), "no existence oracle");
        assertTrue(refused("models/up/secret").contains("leads outside"));
    }

    @Test
    void linkLoopsEnd() throws IOException {
        Files.createSymbolicLink(scenes.resolve("a"), Path.of("b"));
        Files.createSymbolicLink(scenes.resolve("b"), Path.of("a"));
        assertTrue(refused("a").contains("follows more than 40 symbolic links"));
    }

    @Test
    void allowedFoldersWidenTheTree() throws IOException {
        Files.createSymbolicLink(scenes.resolve("out.obj"), outside.resolve("secret"));
        assertEquals(outside.resolve("secret").toRealPath(), resolve("out.obj", outside));
        assertEquals(outside.resolve("secret").toRealPath(), resolve("../outside/secret", outside));
    }

    @Test
    void controlCharactersInTheReferenceAreEscaped() {
        String message = refused("../\u001b[2Jx");
        assertTrue(message.contains("\\u001b[2Jx"), message);
        assertTrue(message.chars().noneMatch(c -> c < 0x20), message);
    }
}
