package obj;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.util.function.BooleanSupplier;

/**
 * The lines of a Wavefront text (OBJ or MTL), counted, each bounded in length and the whole text bounded too: a
 * file without line breaks, or an endless one, is an {@link ObjFormatException}, not an out-of-memory crash.
 */
final class BoundedLines {
    private final BufferedReader in;
    private final String file;
    /** "OBJ" or "MTL", for messages. */
    private final String kind;

    private final int maxLineLength;
    private final long maxCharacters;
    private final StringBuilder line = new StringBuilder();
    private int number;
    private long characters;

    BoundedLines(Reader text, String file, String kind, int maxLineLength, long maxCharacters) {
        this.in = new BufferedReader(text);
        this.file = file;
        this.kind = kind;
        this.maxLineLength = maxLineLength;
        this.maxCharacters = maxCharacters;
    }

    /** Receives the lines of {@link #forEach}. */
    @FunctionalInterface
    interface LineParser {
        /**
         * Parses one line.
         *
         * @param line the line without its terminator
         * @param number its 1-based number
         */
        void parse(String line, int number) throws ObjFormatException;
    }

    /**
     * Hands every line to {@code parser}, in order; an I/O error becomes an {@link ObjFormatException} of
     * {@code name} at the last line handed over. {@code sawStatement} is asked before each further line (see
     * {@link #next}).
     */
    void forEach(String name, LineParser parser, BooleanSupplier sawStatement) throws ObjFormatException {
        int parsed = 0;
        try {
            for (String line = next(false); line != null; line = next(sawStatement.getAsBoolean())) {
                parsed = number;
                parser.parse(line, parsed);
            }
        } catch (IOException e) {
            throw new ObjFormatException(name, parsed, "cannot be read: " + e, e);
        }
    }

    /** The 1-based number of the line last returned (0 before the first). */
    int number() {
        return number;
    }

    /**
     * The next line without its terminator, or null at the end of the text. {@code sawStatement} says whether a
     * line of the format was read: before one, an overlong line means the file is not of this format.
     */
    String next(boolean sawStatement) throws IOException, ObjFormatException {
        line.setLength(0);
        int c = in.read();
        if (c < 0) return null;
        number++;
        while (c >= 0 && c != '\n') {
            if (++characters > maxCharacters) {
                throw new ObjFormatException(
                        file,
                        number,
                        "the file is longer than " + maxCharacters + " characters, the most an " + kind
                                + " file may have here");
            }
            if (c != '\r') line.append((char) c);
            if (line.length() > maxLineLength) {
                throw new ObjFormatException(
                        file,
                        number,
                        sawStatement
                                ? "line longer than " + maxLineLength + " characters"
                                : "line longer than " + maxLineLength + " characters before any " + kind
                                        + " statement: this is not an " + kind + " file");
            }
            c = in.read();
        }
        return line.toString();
    }
}
