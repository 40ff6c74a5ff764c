package distributed;

import cli.RenderOverrides;
import java.io.IOException;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;
import sceneio.LoadedScene;
import sceneio.SceneFileException;
import sceneio.SceneLoader;
import sceneio.model.SceneDocument;

/**
 * A scene file as it travels to the executors: its text, plus the bytes of the files it references (OBJ meshes,
 * their MTL files and textures, all by relative path), so executors need no shared file system. It is broadcast once per executor, not sent with every task.
 * Executors load it with {@link SceneLoader} exactly as the driver did, so they build the same scene.
 */
public final class SceneBundle implements Serializable {
    private static final long serialVersionUID = 1L;

    private final String name;
    private final String text;
    private final RenderOverrides overrides;
    private final String sceneName;
    private final int width, height;
    /** The scene file's folder, relative to the common folder of the scene and the files it references ("" if the same). */
    private final String sceneFolder;
    /** Referenced files by path relative to that common folder ('/'-separated), in the order the scene read them. */
    private final LinkedHashMap<String, byte[]> files;

    private SceneBundle(
            String name,
            LoadedScene loaded,
            String text,
            RenderOverrides overrides,
            String sceneFolder,
            LinkedHashMap<String, byte[]> files) {
        this.name = name;
        this.text = text;
        this.overrides = overrides;
        this.sceneName = loaded.scene().getName();
        this.width = loaded.camera().getNx();
        this.height = loaded.camera().getNy();
        this.sceneFolder = sceneFolder;
        this.files = files;
    }

    /** {@link #read(Path, RenderOverrides)} without overrides. */
    public static SceneBundle read(Path sceneFile) throws SceneFileException {
        return read(sceneFile, new RenderOverrides());
    }

    /**
     * Loads the scene file on the driver with the overrides applied, exactly as {@code raytracer render} does (so
     * a bad file fails here, with the CLI's message, before any task), and bundles its text, the overrides and the
     * files it references (OBJ, MTL, images). Executors apply the same overrides to the same text.
     */
    public static SceneBundle read(Path sceneFile, RenderOverrides overrides) throws SceneFileException {
        // All validation, with file:line:col messages: the CLI's calls, in the CLI's order.
        LoadedScene loaded = SceneLoader.build(overrides.apply(SceneLoader.read(sceneFile)), sceneFile);
        String text;
        try {
            text = Files.readString(sceneFile);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + sceneFile + " again: " + e.getMessage(), e);
        }
        Path folder = sceneFile.toAbsolutePath().getParent();
        List<Path> objFiles = new ArrayList<>();
        // Every file the loader read (OBJ, MTL, images), as the loader found them: relative to the scene's folder.
        for (String reference : loaded.files())
            objFiles.add(folder.resolve(reference).normalize());
        Path root = folder;
        for (Path obj : objFiles) {
            while (root != null && !obj.startsWith(root)) root = root.getParent();
        }
        if (root == null) throw new IllegalStateException("the referenced files share no folder with " + sceneFile);
        LinkedHashMap<String, byte[]> files = new LinkedHashMap<>();
        for (Path obj : objFiles) {
            try {
                files.putIfAbsent(slashes(root.relativize(obj)), Files.readAllBytes(obj));
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read " + obj + " again: " + e.getMessage(), e);
            }
        }
        return new SceneBundle(sceneFile.toString(), loaded, text, overrides, slashes(root.relativize(folder)), files);
    }

    private static String slashes(Path relative) {
        return relative.toString().replace(relative.getFileSystem().getSeparator(), "/");
    }

    /** The scene file as the user named it (for messages). */
    public String name() {
        return name;
    }

    /** The scene's name (the file's "name", else the file name without extension). */
    public String sceneName() {
        return sceneName;
    }

    /** Image width in pixels, from the scene file and the overrides. */
    public int width() {
        return width;
    }

    /** Image height in pixels, from the scene file and the overrides. */
    public int height() {
        return height;
    }

    /** The scene file's text. */
    public String text() {
        return text;
    }

    /** Paths of the bundled files (OBJ, MTL, images), relative to the common folder of the scene and its files. */
    public List<String> objFiles() {
        return List.copyOf(files.keySet());
    }

    /** Bytes that travel: the text's characters and the referenced files. */
    public long size() {
        long size = text.length();
        for (byte[] b : files.values()) size += b.length;
        return size;
    }

    /** The scene file's document with the overrides applied: what is rendered (before a frame's camera move). */
    public SceneDocument document() throws SceneFileException {
        return overrides.apply(SceneLoader.parse(text, name));
    }

    /**
     * Loads the scene (on an executor), after {@code change} of its document, e.g. the camera moved to a frame's
     * pose. The referenced files are written to a temporary folder laid out as on the driver and deleted after loading.
     */
    public LoadedScene load(UnaryOperator<SceneDocument> change) throws SceneFileException {
        SceneDocument document = change.apply(document());
        if (files.isEmpty())
            return SceneLoader.build(document, name, Path.of("").toAbsolutePath(), text);
        Path root = null;
        try {
            root = Files.createTempDirectory("raytracer-scene");
            for (Map.Entry<String, byte[]> f : files.entrySet()) {
                Path target = root.resolve(f.getKey());
                Files.createDirectories(target.getParent());
                Files.write(target, f.getValue());
            }
            return SceneLoader.build(document, name, root.resolve(sceneFolder), text);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the scene's referenced files to a temporary folder: " + e, e);
        } finally {
            if (root != null) deleteQuietly(root);
        }
    }

    private static void deleteQuietly(Path root) {
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) Files.deleteIfExists(p);
        } catch (IOException e) {
            // a leftover temporary folder is harmless; the render's result is what matters
        }
    }
}
