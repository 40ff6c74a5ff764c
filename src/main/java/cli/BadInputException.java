package cli;

/**
 * Input a command cannot use (an output path in a missing folder, an option combination that makes no sense):
 * reported as one line and exit code {@link ExitCodes#BAD_INPUT}, before anything is rendered.
 */
public final class BadInputException extends Exception {
    public BadInputException(String message) {
        super(message);
    }
}
