package cli;

import primitives.Printable;

/**
 * Input a command cannot use (an output path in a missing folder, an option combination that makes no sense):
 * reported as one line and exit code {@link ExitCodes#BAD_INPUT}, before anything is rendered. Control characters
 * in the message (from a path or a value the user gave) are escaped ({@link Printable}).
 */
public final class BadInputException extends Exception {
    /**
     * An input problem described in one line.
     *
     * @param message what is wrong and what is allowed, shown after {@code error: }
     */
    public BadInputException(String message) {
        super(Printable.message(message));
    }
}
