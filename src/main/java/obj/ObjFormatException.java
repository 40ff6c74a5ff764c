package obj;

import primitives.Printable;

/**
 * A Wavefront OBJ or MTL file that cannot be read: it names the file, the line (1-based; 0 when the problem is not
 * on one line, such as a missing file or a file without faces) and the reason. The only exception {@link ObjReader}
 * and {@link MtlReader} throw. Control characters in the message (from a file name or a quoted token) are escaped ({@link Printable}).
 */
public final class ObjFormatException extends Exception {
    /** The file as the caller named it. */
    private final String file;
    /** The 1-based line, or 0 when the problem concerns the whole file. */
    private final int line;
    /** What is wrong and what is allowed. */
    private final String reason;

    /**
     * A problem with no underlying exception.
     *
     * @param file the file as the caller named it
     * @param line the 1-based line, or 0 when the problem concerns the whole file
     * @param reason what is wrong and what is allowed
     */
    public ObjFormatException(String file, int line, String reason) {
        this(file, line, reason, null);
    }

    /**
     * A problem caused by another exception, such as an I/O error.
     *
     * @param file the file as the caller named it
     * @param line the 1-based line, or 0 when the problem concerns the whole file
     * @param reason what is wrong and what is allowed
     * @param cause the underlying exception, or null
     */
    public ObjFormatException(String file, int line, String reason, Throwable cause) {
        super(Printable.message(file) + (line > 0 ? ":" + line : "") + ": " + Printable.message(reason), cause);
        this.file = Printable.message(file);
        this.line = line;
        this.reason = Printable.message(reason);
    }

    /**
     * The file as the caller named it.
     *
     * @return the file name as given, for messages
     */
    public String getFile() {
        return file;
    }

    /**
     * The 1-based line, or 0 when the problem concerns the whole file.
     *
     * @return the 1-based line number, or 0
     */
    public int getLine() {
        return line;
    }

    /**
     * What is wrong and what is allowed, without the file and line.
     *
     * @return the reason alone
     */
    public String getReason() {
        return reason;
    }
}
