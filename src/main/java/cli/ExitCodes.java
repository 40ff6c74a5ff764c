package cli;

/** The exit codes of every subcommand, so scripts can tell a bad scene from a failed render. */
public final class ExitCodes {
    /** The command did what was asked. */
    public static final int OK = 0;
    /** The input was fine but rendering or writing the result failed. */
    public static final int RENDER_FAILED = 1;
    /** Bad input: a scene file, an option or an output path that cannot be used (nothing was rendered). */
    public static final int BAD_INPUT = 2;
    /**
     * The render was cancelled (Ctrl-C, SIGTERM) and nothing was written: 128 + SIGINT, as shells report an
     * interrupted command. (During a JVM shutdown the process' status is the signal's, 130 or 143.)
     */
    public static final int CANCELLED = 130;

    private ExitCodes() {}
}
