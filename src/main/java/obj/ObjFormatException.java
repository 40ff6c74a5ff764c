package obj;

/**
 * A Wavefront OBJ file that cannot be read: it names the file, the line (1-based; 0 when the problem is not on
 * one line, such as a missing file or a file without faces) and the reason. The only exception {@link ObjReader}
 * throws.
 */
public final class ObjFormatException extends Exception {
    private final String file;
    private final int line;
    private final String reason;

    public ObjFormatException(String file, int line, String reason) {
        this(file, line, reason, null);
    }

    public ObjFormatException(String file, int line, String reason, Throwable cause) {
        super(file + (line > 0 ? ":" + line : "") + ": " + reason, cause);
        this.file = file;
        this.line = line;
        this.reason = reason;
    }

    /** The file as the caller named it. */
    public String getFile() {
        return file;
    }

    /** The 1-based line, or 0 when the problem concerns the whole file. */
    public int getLine() {
        return line;
    }

    /** What is wrong and what is allowed, without the file and line. */
    public String getReason() {
        return reason;
    }
}
