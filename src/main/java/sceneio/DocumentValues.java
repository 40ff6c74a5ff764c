package sceneio;

import java.util.List;
import java.util.function.Supplier;
import primitives.Color;
import primitives.Point;
import primitives.Vector;
import sceneio.model.Vec3;

/**
 * A scene document's values as core values, and its problems as {@link SceneFileException}s at their JSON path (with
 * the line and column when the text is known). The core's own {@code IllegalArgumentException} messages say what is
 * allowed, so {@link #core} keeps them and gives them a place.
 */
final class DocumentValues {
    private final String file;
    /** Supplies the document's text, only on error, to find line and column (null: paths only). */
    private final Supplier<String> text;

    /**
     * @param file the scene file's name for messages
     * @param text supplies the document's text, only on error (null: paths only)
     */
    DocumentValues(String file, Supplier<String> text) {
        this.file = file;
        this.text = text;
    }

    /** A constructor or setter of the core (or a step of the builder that calls some). */
    @FunctionalInterface
    interface CoreCall<T> {
        T get() throws SceneFileException;
    }

    /** A core construction whose IllegalArgument/IllegalState message is reported at {@code at}. */
    <T> T core(JsonPath at, CoreCall<T> call) throws SceneFileException {
        try {
            return call.get();
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw fail(at, e.getMessage() == null ? e.toString() : e.getMessage(), e);
        }
    }

    /** {@code value}, or a failure naming the missing {@code field} of {@code parent}. */
    <T> T required(JsonPath parent, String field, T value) throws SceneFileException {
        if (value == null) throw fail(parent, "missing required field \"" + field + "\"");
        return value;
    }

    /** {@code value}, or a failure where JSON's null stands for it. */
    <T> T required(JsonPath at, T value) throws SceneFileException {
        if (value == null) throw fail(at, "null is not allowed here");
        return value;
    }

    Point[] points(JsonPath at, List<Vec3> vertices) throws SceneFileException {
        Point[] points = new Point[vertices.size()];
        for (int i = 0; i < points.length; i++) {
            points[i] = point(at.index(i), required(at.index(i), vertices.get(i)));
        }
        return points;
    }

    Point point(JsonPath at, Vec3 v) throws SceneFileException {
        return core(at, () -> new Point(v.x(), v.y(), v.z()));
    }

    Vector vector(JsonPath at, Vec3 v) throws SceneFileException {
        return core(at, () -> new Vector(v.x(), v.y(), v.z()));
    }

    Color color(JsonPath at, Vec3 v) throws SceneFileException {
        if (v.x() < 0 || v.y() < 0 || v.z() < 0) {
            throw fail(
                    at,
                    "colour channels must be >= 0 (0..255 is the usual range), but were [" + v.x() + ", " + v.y() + ", "
                            + v.z() + "]");
        }
        return new Color(v.x(), v.y(), v.z());
    }

    SceneFileException fail(JsonPath at, String problem) {
        return fail(at, problem, null);
    }

    SceneFileException fail(JsonPath at, String problem, Throwable cause) {
        String source = text == null ? null : text.get();
        int[] place = source == null ? null : JsonLocator.locateNearest(source, at);
        return new SceneFileException(
                file, place == null ? 0 : place[0], place == null ? 0 : place[1], at.toString(), problem, cause);
    }
}
