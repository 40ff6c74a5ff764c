package primitives;

/**
 * Text from input made safe to print in a message: control characters (terminal escape sequences among them)
 * become hexadecimal escapes (ESC is shown as backslash, u, 001b), and long text is cut, so a hostile file can
 * neither drive the user's terminal nor flood it through an error message.
 */
public final class Printable {
    /** Characters kept of quoted input before it is cut with "...". */
    public static final int MAX_LENGTH = 80;

    private Printable() {}

    /**
     * {@code text} with control characters escaped, cut to {@link #MAX_LENGTH} characters.
     *
     * @param text the text to quote, possibly from an untrusted file; may be null
     * @return the escaped text, cut with "..." beyond {@link #MAX_LENGTH} characters, or "null"
     */
    public static String of(String text) {
        return escape(text, MAX_LENGTH);
    }

    /**
     * A whole message with control characters escaped but line breaks kept, uncut: the last line of defence where
     * messages are printed.
     *
     * @param text the message; may be null
     * @return the escaped message, or "null"
     */
    public static String message(String text) {
        if (text == null) return "null";
        StringBuilder out = new StringBuilder(text.length());
        for (String line : text.split("\n", -1)) {
            if (out.length() > 0) out.append('\n');
            out.append(escape(line, Integer.MAX_VALUE));
        }
        return out.toString();
    }

    private static String escape(String text, int max) {
        if (text == null) return "null";
        StringBuilder out = new StringBuilder(Math.min(text.length(), max) + 8);
        int n = Math.min(text.length(), max);
        for (int i = 0; i < n; i++) {
            char c = text.charAt(i);
            if (Character.isISOControl(c) || Character.getType(c) == Character.FORMAT) {
                out.append(String.format("\\u%04x", (int) c));
            } else {
                out.append(c);
            }
        }
        if (text.length() > max) out.append("...");
        return out.toString();
    }
}
