package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link AtomicFile}'s temporary files: short fixed-length names (so a final name of 250 characters still works),
 * in the target's folder while writing, gone afterwards, and leftovers of a killed process older than a day
 * removed by the next write beside them (younger ones, perhaps another process' write in progress, kept).
 */
class AtomicFileTest {
    @TempDir
    Path folder;

    @Test
    void aLongFinalNameGetsAShortTemporaryName() throws IOException {
        Path target = folder.resolve("x".repeat(246) + ".png"); // 250 characters: the temporary name must be shorter
        AtomicReference<Path> seen = new AtomicReference<>();
        AtomicFile.write(target, "image", temp -> {
            seen.set(temp);
            Files.writeString(temp, "data");
        });
        assertEquals("data", Files.readString(target));
        String name = seen.get().getFileName().toString();
        assertTrue(name.startsWith(AtomicFile.TEMP_PREFIX) && name.endsWith(AtomicFile.TEMP_SUFFIX), name);
        assertEquals(31, name.length(), name);
        assertFalse(Files.exists(seen.get()), "the temporary file is gone");
        assertEquals(List.of(target), list());
    }

    @Test
    void staleLeftoversAreRemovedAndFreshOnesKept() throws IOException {
        Path stale = Files.writeString(folder.resolve(AtomicFile.TEMP_PREFIX + "00000000deadbeef.tmp"), "old");
        Files.setLastModifiedTime(stale, FileTime.fromMillis(System.currentTimeMillis() - 2L * 24 * 3600 * 1000));
        Path fresh = Files.writeString(folder.resolve(AtomicFile.TEMP_PREFIX + "00000000cafebabe.tmp"), "new");
        Path unrelated = Files.writeString(folder.resolve(".other.tmp"), "keep");
        Files.setLastModifiedTime(unrelated, FileTime.fromMillis(0));
        AtomicFile.write(folder.resolve("a.png"), "image", temp -> Files.writeString(temp, "a"));
        assertFalse(Files.exists(stale));
        assertTrue(Files.exists(fresh));
        assertTrue(Files.exists(unrelated), "only this class's own temporary files are touched");
    }

    @Test
    void aFailedWriteLeavesNothing() throws IOException {
        Path target = folder.resolve("b.png");
        java.io.UncheckedIOException e = assertThrows(
                java.io.UncheckedIOException.class,
                () -> AtomicFile.write(target, "image", temp -> {
                    Files.writeString(temp, "half");
                    throw new IOException("disk full");
                }));
        assertTrue(e.getMessage().contains("disk full"), e.getMessage());
        assertEquals(List.of(), list());
    }

    private List<Path> list() throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.sorted().toList();
        }
    }
}
