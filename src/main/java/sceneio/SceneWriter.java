package sceneio;

import com.fasterxml.jackson.core.JsonProcessingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import renderer.AtomicFile;
import sceneio.model.SceneDocument;

/**
 * Writes scene documents as JSON in the format {@link SceneLoader} reads: reading what was written gives an equal
 * document. Absent (null) fields are left out, coefficients with equal channels are written as one number, and
 * enum values in lower case.
 */
public final class SceneWriter {
    private SceneWriter() {}

    /**
     * The document as pretty-printed JSON text.
     *
     * @param document the scene document to write
     * @return the JSON text, ending with a newline
     */
    public static String toJson(SceneDocument document) {
        try {
            return SceneJson.MAPPER.writeValueAsString(document) + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("scene document cannot be written as JSON: " + e.getOriginalMessage(), e);
        }
    }

    /**
     * Writes the document to {@code file} through a temporary file, so a failure never leaves half a file.
     *
     * @param document the scene document to write
     * @param file the file to create or replace
     */
    public static void write(SceneDocument document, Path file) {
        String json = toJson(document);
        AtomicFile.write(file, "scene file", temp -> Files.writeString(temp, json, StandardCharsets.UTF_8));
    }
}
