package cli;

/** How render progress is shown on stderr. */
public enum ProgressMode {
    /** A bar when run interactively (a console is attached), plain lines otherwise. */
    AUTO,
    /** An ASCII progress bar redrawn in place. */
    BAR,
    /** One plain line per 10% finished: for logs and CI, where a redrawn bar would be noise. */
    LINES,
    /** Nothing. */
    NONE
}
