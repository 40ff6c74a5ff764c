package obj;

/**
 * What the OBJ and MTL readers do with a line's tokens alike: read a finite number, and quote input in a message
 * (escaped, so that no terminal control sequence reaches the user, and short).
 */
final class Tokens {
    private Tokens() {}

    /**
     * The finite number {@code token} of a {@code keyword} statement on line {@code line} of {@code file}.
     *
     * @throws ObjFormatException naming the file, line, keyword and token if it is not a number or not finite
     */
    static double finite(String token, String keyword, String file, int line) throws ObjFormatException {
        double value;
        try {
            value = Double.parseDouble(token);
        } catch (NumberFormatException e) {
            throw new ObjFormatException(
                    file, line, "'" + keyword + "' value '" + abbreviate(token) + "' is not a number");
        }
        if (!Double.isFinite(value)) {
            throw new ObjFormatException(
                    file, line, "'" + keyword + "' value '" + abbreviate(token) + "' must be a finite number");
        }
        return value;
    }

    /** Input quoted in a message: escaped (no terminal control sequences) and at most 20 characters and "...". */
    static String abbreviate(String s) {
        return primitives.Printable.of(s.length() <= 20 ? s : s.substring(0, 20) + "...");
    }
}
