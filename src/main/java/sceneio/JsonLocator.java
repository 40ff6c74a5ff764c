package sceneio;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import java.io.IOException;

/**
 * Finds the line and column of a JSON path in a document's text. Errors found after parsing (a negative radius, an
 * unknown material) know only their path; the text is scanned again for the place, which costs nothing on
 * success because it happens only on error.
 */
final class JsonLocator {
    private static final JsonFactory FACTORY = JsonFactory.builder()
            .enable(JsonReadFeature.ALLOW_JAVA_COMMENTS)
            .streamReadConstraints(StreamReadConstraints.builder()
                    .maxNestingDepth(SceneJson.MAX_NESTING)
                    .build())
            .build();

    private JsonLocator() {}

    /**
     * Line and column of {@code path}, or of its nearest enclosing value that is in the text (a missing field has
     * no place of its own); null if none is found.
     */
    static int[] locateNearest(String text, JsonPath path) {
        for (JsonPath p = path; p != null; p = p.parent()) {
            int[] place = locate(text, p);
            if (place != null) return place;
        }
        return null;
    }

    /** Line and column (1-based) of the value or field name at {@code path}, or null if it is not in the text. */
    static int[] locate(String text, JsonPath path) {
        String target = path.toPointer();
        try (JsonParser p = FACTORY.createParser(text)) {
            for (JsonToken t = p.nextToken(); t != null; t = p.nextToken()) {
                // At a field name the context already points at that field; elsewhere at the value itself.
                if (p.getParsingContext().pathAsPointer().toString().equals(target)) {
                    JsonLocation at = p.currentTokenLocation();
                    return new int[] {at.getLineNr(), at.getColumnNr()};
                }
            }
        } catch (IOException | RuntimeException e) {
            return null; // the document parsed before, so this is only a best effort for the message
        }
        return null;
    }
}
