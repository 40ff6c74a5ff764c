package sceneio;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.exc.InputCoercionException;
import com.fasterxml.jackson.core.exc.StreamReadException;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.exc.InvalidFormatException;
import com.fasterxml.jackson.databind.exc.InvalidTypeIdException;
import com.fasterxml.jackson.databind.exc.MismatchedInputException;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.databind.exc.ValueInstantiationException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import sceneio.model.GeometryDocument;
import sceneio.model.LightDocument;

/**
 * Turns Jackson's exceptions into {@link SceneFileException}s that say, in the scene file's terms, where the
 * problem is (line:column and JSON path) and what is allowed there, without Java class names.
 */
final class JsonErrors {
    private static final Map<Class<?>, String> TYPE_KINDS = Map.of(
            GeometryDocument.class,
            "geometry type (sphere, plane, triangle, polygon, tube, cylinder, mesh, group, instance)",
            LightDocument.class,
            "light type (point, spot, directional)");

    private JsonErrors() {}

    /**
     * @param text the document, to place errors at their field rather than where Jackson stopped reading (which
     *     for records is often the end of the object)
     */
    static SceneFileException translate(String file, String text, JsonProcessingException e) {
        JsonLocation at = e.getLocation();
        int line = at == null ? 0 : Math.max(at.getLineNr(), 0);
        int column = at == null ? 0 : Math.max(at.getColumnNr(), 0);
        JsonPath path = e instanceof JsonMappingException m ? path(m) : null;
        boolean syntax = e instanceof StreamReadException || e.getCause() instanceof StreamReadException;
        if (path != null && !syntax && path.parent() != null) {
            int[] place = JsonLocator.locateNearest(text, path);
            if (place != null) {
                line = place[0];
                column = place[1];
            }
        }
        return new SceneFileException(
                file,
                line,
                column,
                path == null ? null : primitives.Printable.message(path.toString()),
                primitives.Printable.message(problem(e)),
                e);
    }

    private static String problem(JsonProcessingException e) {
        if (e instanceof StreamReadException || e.getCause() instanceof StreamReadException) {
            JsonProcessingException read = e instanceof StreamReadException ? e : (StreamReadException) e.getCause();
            if (read instanceof InputCoercionException c) {
                return "number out of range: " + firstLine(c.getOriginalMessage());
            }
            return "malformed JSON: " + firstLine(read.getOriginalMessage());
        }
        if (e instanceof UnrecognizedPropertyException u) {
            return "unknown field \"" + u.getPropertyName() + "\"; allowed fields here: "
                    + sorted(u.getKnownPropertyIds());
        }
        if (e instanceof InvalidTypeIdException t) {
            String kind = TYPE_KINDS.getOrDefault(t.getBaseType().getRawClass(), "type");
            if (t.getTypeId() == null) return "missing \"type\": give the " + kind;
            return "unknown "
                    + kind.replace(" (", " \"" + t.getTypeId() + "\"; allowed: ")
                            .replace(")", "");
        }
        if (e instanceof InvalidFormatException f
                && f.getTargetType() != null
                && f.getTargetType().isEnum()) {
            return "\"" + f.getValue() + "\" is not allowed here; allowed: "
                    + String.join(", ", enumNames(f.getTargetType()));
        }
        if (e instanceof ValueInstantiationException) {
            return "invalid value: " + cause(e);
        }
        if (e instanceof MismatchedInputException m) {
            String original = firstLine(m.getOriginalMessage());
            if (original.startsWith("No content to map")) {
                return "the file is empty: expected a JSON object holding the scene";
            }
            if (original.startsWith("Trailing token")) {
                return "unexpected content after the scene object: a scene file holds exactly one JSON object";
            }
            // Messages of our own (de)serializers already say what is expected; Jackson's name Java types.
            if (original.startsWith("expected") || original.contains("must be") || m.getTargetType() == null) {
                return original;
            }
            return "wrong type: expected " + expected(m.getTargetType()) + foundSuffix(original);
        }
        return firstLine(e.getOriginalMessage());
    }

    /** Jackson's words for the input it found, e.g. "String value ("800")" in "Cannot coerce String value ...". */
    private static final Pattern COERCE = Pattern.compile("Cannot coerce ([A-Za-z-]+) value \\((.{0,60}?)\\) to");

    private static final Pattern FROM = Pattern.compile("from ([A-Za-z-]+) value");

    /** The offending input in words, e.g. {@code a string ("800")}, read from Jackson's message. */
    private static String foundSuffix(String message) {
        Matcher m = COERCE.matcher(message);
        if (m.find()) return ", but found " + shape(m.group(1)) + " (" + m.group(2) + ")";
        m = FROM.matcher(message);
        if (m.find()) return ", but found " + shape(m.group(1));
        return "";
    }

    private static String shape(String jacksonShape) {
        return switch (jacksonShape) {
            case "String" -> "a string";
            case "Integer" -> "an integer";
            case "Floating-point" -> "a number with a fraction";
            case "Boolean" -> "a boolean";
            case "Array" -> "an array";
            case "Object" -> "an object";
            case "Null" -> "null";
            default -> jacksonShape.toLowerCase(Locale.ROOT);
        };
    }

    /** What a Java target type is called in the scene file's terms. */
    private static String expected(Class<?> type) {
        if (type == Double.class || type == double.class) return "a number";
        if (type == Integer.class || type == int.class || type == Long.class || type == long.class) {
            return "an integer";
        }
        if (type == Boolean.class || type == boolean.class) return "true or false";
        if (type == String.class) return "a string";
        if (List.class.isAssignableFrom(type) || type.isArray()) return "an array";
        if (Map.class.isAssignableFrom(type)) return "an object of named entries";
        if (type.isEnum()) return "one of " + String.join(", ", enumNames(type));
        if (TYPE_KINDS.containsKey(type)) return "an object with a \"type\"";
        return "an object";
    }

    private static List<String> enumNames(Class<?> type) {
        List<String> names = new ArrayList<>();
        for (Object c : type.getEnumConstants()) names.add(c.toString().toLowerCase(Locale.ROOT));
        return names;
    }

    private static String sorted(Collection<Object> ids) {
        TreeSet<String> names = new TreeSet<>();
        for (Object id : ids) names.add(String.valueOf(id));
        return String.join(", ", names);
    }

    /** The JSON path of the reference chain, e.g. {@code $.geometries[2].radius}. */
    private static JsonPath path(JsonMappingException e) {
        JsonPath path = JsonPath.ROOT;
        for (JsonMappingException.Reference r : e.getPath()) {
            if (r.getFieldName() != null) path = path.field(r.getFieldName());
            else if (r.getIndex() >= 0) path = path.index(r.getIndex());
        }
        return path;
    }

    private static String cause(Throwable e) {
        Throwable c = e;
        while (c.getCause() != null && c.getCause() != c) c = c.getCause();
        return firstLine(c.getMessage());
    }

    /** Jackson appends source excerpts and reference chains on further lines; the first line is the message. */
    private static String firstLine(String message) {
        if (message == null) return "invalid input";
        int newline = message.indexOf('\n');
        return (newline < 0 ? message : message.substring(0, newline)).strip();
    }
}
