package sceneio;

import com.fasterxml.jackson.core.JsonProcessingException;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Supplier;
import renderer.RenderMemory;
import sceneio.model.SceneDocument;

/**
 * Loads JSON scene files (format: docs/SCENE-FORMAT.md). {@link #read} parses a file into a
 * {@link SceneDocument} (syntax and types); {@link #build} turns a document into a scene and camera (required
 * fields, value ranges, OBJ meshes); {@link #load} does both. Every problem is a {@link SceneFileException} that
 * names the file, the line:column and JSON path, and what is allowed; no other exception escapes.
 *
 * <pre>{@code
 * LoadedScene loaded = SceneLoader.load(Path.of("scenes/showcase.json"));
 * loaded.camera().renderImage().writeToImage(Path.of("images/showcase.png"));
 * }</pre>
 */
public final class SceneLoader {
    /** Largest scene file read: 64 MiB (a scene holds meshes by reference, in OBJ files). */
    public static final int MAX_SCENE_BYTES = 64 << 20;
    /**
     * Heap a scene file may take per byte while it is read and built: its text, the document and the core objects
     * (6 measured on files of spheres and of long vertex lists; the accelerator is counted when the render starts).
     */
    public static final int BYTES_PER_SCENE_BYTE = 12;

    private SceneLoader() {}

    /**
     * Reads and builds a scene file; OBJ paths are relative to its folder, and must resolve (links followed) inside
     * its folder tree.
     *
     * @param file the JSON scene file
     * @return the scene, its camera, the document read and the warnings
     * @throws SceneFileException if the file or a file it references cannot be read or is not a valid scene
     */
    public static LoadedScene load(Path file) throws SceneFileException {
        return load(file, List.of());
    }

    /**
     * {@link #load(Path)}, with files referenced from the scene allowed in {@code allowedFolders} too.
     *
     * @param file the JSON scene file
     * @param allowedFolders further folders whose files the scene may reference; not null, may be empty
     * @return the scene, its camera, the document read and the warnings
     * @throws SceneFileException if the file or a file it references cannot be read or is not a valid scene
     */
    public static LoadedScene load(Path file, List<Path> allowedFolders) throws SceneFileException {
        String text = text(file);
        SceneDocument document = parse(text, file.toString());
        return new SceneBuilder(file.toString(), baseDir(file), () -> text, allowedFolders)
                .build(document, sceneName(file.toString()));
    }

    /**
     * Builds a document read from {@code file} (and perhaps changed since): OBJ paths are relative to the file's
     * folder, and the file is read again only on error, to give the message a line and column.
     *
     * @param document the scene document to build
     * @param file the file the document was read from, for relative paths and messages
     * @return the scene, its camera, the document and the warnings
     * @throws SceneFileException if the document is not a valid scene or a referenced file cannot be read
     */
    public static LoadedScene build(SceneDocument document, Path file) throws SceneFileException {
        return build(document, file, List.of());
    }

    /**
     * {@link #build(SceneDocument, Path)}, with referenced files allowed in {@code allowedFolders} too.
     *
     * @param document the scene document to build
     * @param file the file the document was read from, for relative paths and messages
     * @param allowedFolders further folders whose files the scene may reference; not null, may be empty
     * @return the scene, its camera, the document and the warnings
     * @throws SceneFileException if the document is not a valid scene or a referenced file cannot be read
     */
    public static LoadedScene build(SceneDocument document, Path file, List<Path> allowedFolders)
            throws SceneFileException {
        Supplier<String> text = () -> {
            try {
                return Files.readString(file);
            } catch (IOException | RuntimeException e) {
                return null; // the message then gives the JSON path alone
            }
        };
        return new SceneBuilder(file.toString(), baseDir(file), text, allowedFolders)
                .build(document, sceneName(file.toString()));
    }

    /**
     * Reads a scene file into a document without building it (to change it, or to write it back).
     *
     * @param file the JSON scene file
     * @return the document as read, with absent fields null
     * @throws SceneFileException if the file cannot be read or is not valid scene JSON
     */
    public static SceneDocument read(Path file) throws SceneFileException {
        return parse(text(file), file.toString());
    }

    /**
     * Parses scene JSON; {@code name} names it in messages.
     *
     * @param json the scene file's text
     * @param name the file name shown in messages
     * @return the document as read, with absent fields null
     * @throws SceneFileException if the text is not valid scene JSON
     */
    public static SceneDocument parse(String json, String name) throws SceneFileException {
        String start = json.stripLeading();
        if (!start.isEmpty() && start.charAt(0) != '{' && start.charAt(0) != '/') {
            // Not JSON at all (nor a comment before it): say so without quoting it, it may be any file.
            throw new SceneFileException(
                    name,
                    0,
                    0,
                    null,
                    "is not a JSON scene file: a scene file holds one JSON object, starting with '{'",
                    null);
        }
        SceneDocument document;
        try {
            document = SceneJson.MAPPER.readValue(json, SceneDocument.class);
        } catch (JsonProcessingException e) {
            throw JsonErrors.translate(name, json, e);
        }
        if (document == null) {
            throw new SceneFileException(
                    name, 1, 1, null, "expected a JSON object holding the scene, but found null", null);
        }
        return document;
    }

    /**
     * Builds a document into a scene and camera.
     *
     * @param name the file name for messages (and the scene's default name)
     * @param baseDir the folder that OBJ paths are relative to
     * @param text the document's text, used only to give errors a line and column (may be null)
     * @param document the scene document to build
     * @return the scene, its camera, the document and the warnings
     * @throws SceneFileException if the document is not a valid scene or a referenced file cannot be read
     */
    public static LoadedScene build(SceneDocument document, String name, Path baseDir, String text)
            throws SceneFileException {
        return new SceneBuilder(name, baseDir, text == null ? null : () -> text, List.of())
                .build(document, sceneName(name));
    }

    /**
     * Parses and builds scene JSON held in a string; OBJ paths are relative to {@code baseDir}.
     *
     * @param json the scene file's text
     * @param name the file name for messages (and the scene's default name)
     * @param baseDir the folder that OBJ paths are relative to
     * @return the scene, its camera, the document read and the warnings
     * @throws SceneFileException if the JSON is not a valid scene or a referenced file cannot be read
     */
    public static LoadedScene load(String json, String name, Path baseDir) throws SceneFileException {
        return build(parse(json, name), name, baseDir, json);
    }

    private static String text(Path file) throws SceneFileException {
        return text(file, "scene file");
    }

    /** The file's text, strictly UTF-8; {@code kind} names the file in messages ("scene file"). */
    static String text(Path file, String kind) throws SceneFileException {
        String name = file.toString();
        if (Files.isDirectory(file)) {
            throw new SceneFileException(name, 0, 0, null, "is a folder, not a " + kind, null);
        }
        if (Files.exists(file) && !Files.isRegularFile(file)) {
            // A device or a pipe (/dev/zero, /dev/stdin) has no size to check and may never end.
            throw new SceneFileException(name, 0, 0, null, "is not a regular file, so it cannot be a " + kind, null);
        }
        try {
            long size = Files.size(file);
            if (size > MAX_SCENE_BYTES) {
                throw new SceneFileException(
                        name,
                        0,
                        0,
                        null,
                        "is " + size + " bytes; a " + kind + " may have at most " + MAX_SCENE_BYTES
                                + " bytes (64 MiB: meshes belong in OBJ files)",
                        null);
            }
            long needed = size * BYTES_PER_SCENE_BYTE;
            if (needed > RenderMemory.available()) {
                System.gc(); // garbage counts as used until collected: confirm before refusing
                if (needed > RenderMemory.available()) {
                    throw new SceneFileException(
                            name,
                            0,
                            0,
                            null,
                            "is " + size + " bytes; reading it needs up to " + RenderMemory.bytes(needed)
                                    + " of memory ("
                                    + BYTES_PER_SCENE_BYTE + " per byte), but this JVM can give "
                                    + RenderMemory.bytes(RenderMemory.available())
                                    + "; give Java more memory (-Xmx)",
                            null);
                }
            }
            byte[] bytes;
            try (var in = Files.newInputStream(file)) {
                // Bounded even if the file grows while it is read.
                bytes = in.readNBytes(MAX_SCENE_BYTES + 1);
            }
            if (bytes.length > MAX_SCENE_BYTES) {
                throw new SceneFileException(name, 0, 0, null, "grew beyond " + MAX_SCENE_BYTES + " bytes", null);
            }
            // Strict UTF-8: a file in another encoding is reported instead of being read as garbage.
            return StandardCharsets.UTF_8
                    .newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes))
                    .toString();
        } catch (NoSuchFileException e) {
            throw new SceneFileException(name, 0, 0, null, kind + " not found", e);
        } catch (CharacterCodingException e) {
            throw new SceneFileException(name, 0, 0, null, "is not UTF-8 text: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new SceneFileException(name, 0, 0, null, "cannot be read: " + e, e);
        }
    }

    private static Path baseDir(Path file) {
        Path parent = file.toAbsolutePath().getParent();
        return parent == null ? Path.of("").toAbsolutePath() : parent;
    }

    /** The file name without folder and extension: the scene's name when the file gives none. */
    private static String sceneName(String name) {
        String base = Path.of(name).getFileName() == null
                ? name
                : Path.of(name).getFileName().toString();
        int dot = base.lastIndexOf('.');
        return dot > 0 ? base.substring(0, dot) : base;
    }
}
