package renderer;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes a file all or nothing: the bytes go to a hidden temporary file in the target's folder, which is moved over
 * the target only when complete (atomically where the file system can). A failure leaves the previous file, if
 * any, untouched and no temporary file behind. The temporary file is created with the default permissions (the
 * process' umask), not the owner-only ones of {@link Files#createTempFile}, so the result is readable like any
 * file the user creates.
 *
 * <p>Temporary names are short and fixed in length ({@code .raytracer-<16 hex digits>.tmp}, 31 characters), so
 * they fit the file system wherever the final name does. Temporary files still being written when the JVM shuts
 * down (Ctrl-C, SIGTERM) are deleted by a shutdown hook; only a SIGKILL or a power cut can leave one, hidden,
 * and such leftovers older than a day are removed the next time a file is written to that folder.
 */
public final class AtomicFile {
    /** What writes the content, given the temporary file to write it to. */
    @FunctionalInterface
    public interface Content {
        /**
         * Writes the whole content to {@code temp}.
         *
         * @param temp the temporary file beside the target, to be filled
         * @throws IOException if writing fails; the temporary file is then deleted and the target left as it was
         */
        void writeTo(Path temp) throws IOException;
    }

    /** Prefix and suffix of every temporary file this class creates. */
    static final String TEMP_PREFIX = ".raytracer-", TEMP_SUFFIX = ".tmp";
    /** Leftover temporary files older than this are deleted when a file is written beside them. */
    private static final long STALE_MILLIS = 24L * 60 * 60 * 1000;
    /** Temporary files being written right now, for the shutdown hook. */
    private static final Set<Path> IN_FLIGHT = ConcurrentHashMap.newKeySet();

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(AtomicFile::deleteInFlight, "atomic-file-cleanup"));
    }

    private AtomicFile() {}

    private static void deleteInFlight() {
        for (Path temp : IN_FLIGHT) {
            try {
                Files.deleteIfExists(temp);
            } catch (IOException ignored) {
                // shutting down: nothing more to do
            }
        }
    }

    /**
     * Writes {@code file} (parent folders created as needed) and returns its absolute path; an I/O failure is an
     * {@link UncheckedIOException} whose message starts with {@code what} and the file.
     *
     * @param file the file to create or replace
     * @param what what the file is, for the error message (e.g. "image")
     * @param content writes the bytes to the temporary file
     * @return the absolute path of the written file
     * @throws UncheckedIOException if a folder cannot be created or the content cannot be written or moved into place
     */
    public static Path write(Path file, String what, Content content) {
        Path target = file.toAbsolutePath();
        Path temp = null, created = null;
        try {
            Files.createDirectories(target.getParent());
            deleteStaleTemps(target.getParent());
            temp = created = createTemp(target);
            IN_FLIGHT.add(created);
            content.writeTo(temp);
            try {
                Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            temp = null;
            return target;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + what + " " + target + ": " + e.getMessage(), e);
        } finally {
            if (temp != null) {
                try {
                    Files.deleteIfExists(temp);
                } catch (IOException ignored) {
                    // the original error is the one worth reporting
                }
            }
            if (created != null) IN_FLIGHT.remove(created);
        }
    }

    /** Deletes this class's temporary files in {@code folder} older than a day (left by a killed process). */
    private static void deleteStaleTemps(Path folder) {
        long cutoff = System.currentTimeMillis() - STALE_MILLIS;
        try (var entries = Files.newDirectoryStream(folder, TEMP_PREFIX + "*" + TEMP_SUFFIX)) {
            for (Path leftover : entries) {
                if (Files.isRegularFile(leftover, java.nio.file.LinkOption.NOFOLLOW_LINKS)
                        && Files.getLastModifiedTime(leftover).toMillis() < cutoff) {
                    Files.deleteIfExists(leftover);
                }
            }
        } catch (IOException | RuntimeException ignored) {
            // best effort: a leftover is hidden and harmless
        }
    }

    private static Path createTemp(Path target) throws IOException {
        for (int attempt = 0; ; attempt++) {
            String name = TEMP_PREFIX
                    + String.format("%016x", ThreadLocalRandom.current().nextLong())
                    + TEMP_SUFFIX;
            try {
                return Files.createFile(target.resolveSibling(name));
            } catch (FileAlreadyExistsException e) {
                if (attempt == 10) throw e;
            }
        }
    }
}
