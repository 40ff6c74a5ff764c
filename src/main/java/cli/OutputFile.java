package cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Checks, before anything is rendered, that an image can be written where the user asked: a {@code .png} file in
 * an existing, writable folder. Only the default folder {@code images/} is created when missing; a typo in an
 * explicit folder should be an error, not a new folder. Public so that other commands (the Spark jobs) check
 * their output the same way.
 */
public final class OutputFile {
    private OutputFile() {}

    /** The validated target path. */
    public static Path check(Path file, boolean createFolder) throws BadInputException {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        if (!name.toLowerCase(Locale.ROOT).endsWith(".png") || name.length() <= 4) {
            throw new BadInputException("output " + file + ": must be a .png file name, e.g. images/scene.png");
        }
        if (Files.isDirectory(file)) {
            throw new BadInputException("output " + file + ": is a folder; give a .png file name inside it");
        }
        Path folder = file.toAbsolutePath().getParent();
        if (createFolder && !Files.exists(folder)) {
            try {
                Files.createDirectories(folder);
            } catch (IOException e) {
                throw new BadInputException("output " + file + ": cannot create folder " + folder + ": " + e);
            }
        }
        if (!Files.exists(folder)) {
            throw new BadInputException("output " + file + ": folder " + folder + " does not exist (create it first)");
        }
        if (!Files.isDirectory(folder)) {
            throw new BadInputException("output " + file + ": " + folder + " is not a folder");
        }
        // Files.isWritable is not enough (root ignores permission bits, read-only mounts, ACLs): try it.
        try {
            Path probe = Files.createTempFile(folder, ".raytracer-probe", ".tmp");
            Files.delete(probe);
        } catch (IOException | SecurityException e) {
            throw new BadInputException("output " + file + ": folder " + folder + " is not writable (" + e + ")");
        }
        return file;
    }
}
