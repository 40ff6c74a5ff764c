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
import java.util.function.Supplier;
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
    private SceneLoader() {}

    /** Reads and builds a scene file; OBJ paths are relative to its folder. */
    public static LoadedScene load(Path file) throws SceneFileException {
        String text = text(file);
        SceneDocument document = parse(text, file.toString());
        return build(document, file.toString(), baseDir(file), text);
    }

    /**
     * Builds a document read from {@code file} (and perhaps changed since): OBJ paths are relative to the file's
     * folder, and the file is read again only on error, to give the message a line and column.
     */
    public static LoadedScene build(SceneDocument document, Path file) throws SceneFileException {
        Supplier<String> text = () -> {
            try {
                return Files.readString(file);
            } catch (IOException | RuntimeException e) {
                return null; // the message then gives the JSON path alone
            }
        };
        return new SceneBuilder(file.toString(), baseDir(file), text).build(document, sceneName(file.toString()));
    }

    /** Reads a scene file into a document without building it (to change it, or to write it back). */
    public static SceneDocument read(Path file) throws SceneFileException {
        return parse(text(file), file.toString());
    }

    /** Parses scene JSON; {@code name} names it in messages. */
    public static SceneDocument parse(String json, String name) throws SceneFileException {
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
     */
    public static LoadedScene build(SceneDocument document, String name, Path baseDir, String text)
            throws SceneFileException {
        return new SceneBuilder(name, baseDir, text == null ? null : () -> text).build(document, sceneName(name));
    }

    /** Parses and builds scene JSON held in a string; OBJ paths are relative to {@code baseDir}. */
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
        try {
            byte[] bytes = Files.readAllBytes(file);
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
