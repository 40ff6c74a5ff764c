package sceneio;

import primitives.Printable;

/**
 * A scene file that cannot be loaded: the only exception the loader throws. It names the file, the place (line
 * and column when known, and the JSON path) and what is wrong and allowed, in a compiler-like message such as
 * {@code scenes/a.json:12:19: $.geometries[2].radius: sphere radius must be positive and finite, but was -5}.
 * Control characters in any part (a JSON key or name may hold terminal escapes) are escaped ({@link Printable}).
 */
public final class SceneFileException extends Exception {
    /** The scene file as the user named it. */
    private final String file;
    /** 1-based line, or 0 if unknown. */
    private final int line;
    /** 1-based column, or 0 if unknown. */
    private final int column;
    /** Where in the document, or null when not inside a value. */
    private final String jsonPath;
    /** What is wrong and what is allowed. */
    private final String problem;

    /**
     * @param file the scene file as the user named it
     * @param line 1-based line, or 0 if unknown
     * @param column 1-based column, or 0 if unknown
     * @param jsonPath where in the document, e.g. {@code $.camera.up}, or null when not inside a value
     * @param problem what is wrong and what is allowed
     * @param cause the underlying exception, or null
     */
    public SceneFileException(String file, int line, int column, String jsonPath, String problem, Throwable cause) {
        super(format(file, line, column, jsonPath, problem), cause);
        this.file = Printable.message(file);
        this.line = line;
        this.column = column;
        this.jsonPath = jsonPath == null ? null : Printable.message(jsonPath);
        this.problem = Printable.message(problem);
    }

    /** The message, with control characters escaped: names and keys come from the file, which may be hostile. */
    private static String format(String file, int line, int column, String jsonPath, String problem) {
        StringBuilder s = new StringBuilder(Printable.message(file));
        if (line > 0) {
            s.append(':').append(line);
            if (column > 0) s.append(':').append(column);
        }
        s.append(": ");
        if (jsonPath != null) s.append(Printable.message(jsonPath)).append(": ");
        return s.append(Printable.message(problem)).toString();
    }

    /**
     * The scene file as the user named it.
     *
     * @return the file name as given, for messages
     */
    public String getFile() {
        return file;
    }

    /**
     * 1-based line, or 0 if unknown.
     *
     * @return the 1-based line of the problem, or 0 if unknown
     */
    public int getLine() {
        return line;
    }

    /**
     * 1-based column, or 0 if unknown.
     *
     * @return the 1-based column of the problem, or 0 if unknown
     */
    public int getColumn() {
        return column;
    }

    /**
     * The JSON path ({@code $.a.b[2]}), or null.
     *
     * @return the JSON path of the problem, or null when it is not inside a value
     */
    public String getJsonPath() {
        return jsonPath;
    }

    /**
     * What is wrong and allowed, without the place.
     *
     * @return the description of what is wrong and what is allowed
     */
    public String getProblem() {
        return problem;
    }
}
