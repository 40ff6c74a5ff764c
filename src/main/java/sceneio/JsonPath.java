package sceneio;

import java.util.ArrayList;
import java.util.List;

/**
 * A place in a JSON document, shown as {@code $.geometries[2].radius} in messages and convertible to a JSON
 * Pointer ({@code /geometries/2/radius}) to find its line and column. Immutable.
 */
public final class JsonPath {
    /** The document root, {@code $}. */
    public static final JsonPath ROOT = new JsonPath(List.of());

    /** Each segment is a field name (String) or an array index (Integer). */
    private final List<Object> segments;

    private JsonPath(List<Object> segments) {
        this.segments = segments;
    }

    /**
     * The path of field {@code name} of the object here.
     *
     * @param name the field name, any string
     * @return a new path one field deeper than this one
     */
    public JsonPath field(String name) {
        return append(name);
    }

    /**
     * The path of element {@code index} of the array here.
     *
     * @param index the 0-based array index
     * @return a new path one array element deeper than this one
     */
    public JsonPath index(int index) {
        return append(index);
    }

    private JsonPath append(Object segment) {
        List<Object> more = new ArrayList<>(segments);
        more.add(segment);
        return new JsonPath(List.copyOf(more));
    }

    /**
     * The enclosing value's path, or null at the root.
     *
     * @return the path of the enclosing object or array, or null if this is the root
     */
    public JsonPath parent() {
        return segments.isEmpty() ? null : new JsonPath(segments.subList(0, segments.size() - 1));
    }

    /**
     * The same place as a JSON Pointer (RFC 6901), e.g. {@code /geometries/2/radius}.
     *
     * @return the JSON Pointer, the empty string for the root
     */
    public String toPointer() {
        StringBuilder s = new StringBuilder();
        for (Object segment : segments) {
            s.append('/').append(segment.toString().replace("~", "~0").replace("/", "~1"));
        }
        return s.toString();
    }

    /** For messages: {@code $.a.b[2]}, with {@code ['odd name']} for names that are not plain identifiers. */
    @Override
    public String toString() {
        StringBuilder s = new StringBuilder("$");
        for (Object segment : segments) {
            if (segment instanceof Integer i) {
                s.append('[').append(i).append(']');
            } else {
                String name = (String) segment;
                if (name.matches("[A-Za-z_][A-Za-z0-9_]*")) s.append('.').append(name);
                else
                    s.append("['")
                            .append(name.replace("\\", "\\\\").replace("'", "\\'"))
                            .append("']");
            }
        }
        return s.toString();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof JsonPath p && p.segments.equals(segments);
    }

    @Override
    public int hashCode() {
        return segments.hashCode();
    }
}
