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

    /** Longest scene name the default output file takes (bytes of UTF-8; file systems allow 255 per name). */
    static final int MAX_NAME_BYTES = 200;

    /**
     * The default output of a scene rendered without {@code -o}: {@code images/<name>.png}. The name comes from the
     * scene file, so it must be a plain file name: no folder separators, no {@code ..}, no control characters, at
     * most {@value #MAX_NAME_BYTES} bytes; otherwise the user is asked for {@code -o}.
     *
     * @param sceneName the scene's name, as given by the scene file; may be null
     * @return the relative path {@code images/<sceneName>.png}
     * @throws BadInputException if the name is empty, has a separator or control character, starts with '.' or is too
     *     long
     */
    public static Path defaultFor(String sceneName) throws BadInputException {
        String problem = null;
        if (sceneName == null || sceneName.isBlank()) {
            problem = "is empty";
        } else if (sceneName.contains("/") || sceneName.contains("\\")) {
            problem = "contains a folder separator";
        } else if (sceneName.equals(".") || sceneName.equals("..") || sceneName.startsWith(".")) {
            problem = "starts with '.'";
        } else if (sceneName.chars().anyMatch(c -> Character.isISOControl(c))) {
            problem = "contains control characters";
        } else if (sceneName.getBytes(java.nio.charset.StandardCharsets.UTF_8).length > MAX_NAME_BYTES) {
            problem = "is longer than " + MAX_NAME_BYTES + " bytes";
        }
        if (problem != null) {
            throw new BadInputException("scene name \"" + primitives.Printable.of(sceneName) + "\" " + problem
                    + ", so it cannot name the default output images/<name>.png; give the output with -o FILE.png");
        }
        return Path.of("images", sceneName + ".png");
    }

    /**
     * The validated target path.
     *
     * @param file the PNG file the user asked for
     * @param createFolder true to create the file's folder when missing (only for the default {@code images/})
     * @return {@code file}, unchanged
     * @throws BadInputException if the name does not end in {@code .png} or is too long, the file is a folder, or its
     *     folder is missing (and not created), not a folder or not writable
     */
    public static Path check(Path file, boolean createFolder) throws BadInputException {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        if (!name.toLowerCase(Locale.ROOT).endsWith(".png") || name.length() <= 4) {
            throw new BadInputException("output " + file + ": must be a .png file name, e.g. images/scene.png");
        }
        if (name.getBytes(java.nio.charset.StandardCharsets.UTF_8).length > 255) {
            throw new BadInputException("output " + primitives.Printable.of(file.toString())
                    + ": the file name is longer than 255 bytes, the most file systems allow");
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
