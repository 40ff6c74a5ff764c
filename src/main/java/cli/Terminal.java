package cli;

import java.io.Console;

/** Whether a person is watching this process' terminal, for progress bars. */
final class Terminal {
    private Terminal() {}

    /**
     * Whether a person is watching a terminal. Java 17 has a console only when stdin and stdout are terminals;
     * from Java 22 a console may exist when redirected, so its {@code isTerminal()} (absent before 22) decides.
     */
    static boolean interactive() {
        Console console = System.console();
        if (console == null || "dumb".equals(System.getenv("TERM"))) return false;
        try {
            return (Boolean) Console.class.getMethod("isTerminal").invoke(console);
        } catch (ReflectiveOperationException | RuntimeException e) {
            return true; // Java 17 to 21: a console means a terminal
        }
    }
}
