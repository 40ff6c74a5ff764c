package cli;

import java.io.PrintWriter;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import sceneio.SceneFileException;

/**
 * The {@code raytracer} command line: {@code raytracer render scene.json -o out.png}, {@code --help},
 * {@code --version}, and {@code raytracer --daemon render ...} to render in a JVM that stays warm between commands
 * ({@link RenderDaemon}). Exit codes are in {@link ExitCodes}: 0 success, 1 render failure, 2 bad input.
 *
 * <p>Subcommands: {@code render}, {@code report} (accuracy against time), {@code robustness} (hard-case metrics),
 * {@code benchmark bvh|planning|effects}. To add one, write a picocli {@code @Command} class that
 * implements {@code Callable<Integer>} and add it to {@code subcommands} below. Throw {@link SceneFileException}
 * or {@link BadInputException} for bad input; anything else is reported as a failure (exit 1).
 */
@Command(
        name = "raytracer",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Renders JSON scene files (docs/SCENE-FORMAT.md) into PNG images.",
        subcommands = {
            RenderCommand.class,
            ReportCommand.class,
            RobustnessCommand.class,
            BenchmarkCommand.class,
            CommandLine.HelpCommand.class
        },
        exitCodeOnInvalidInput = ExitCodes.BAD_INPUT,
        exitCodeOnExecutionException = ExitCodes.RENDER_FAILED)
public final class RaytracerCli implements Runnable {
    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    /** Shown in the usage; a first {@code --daemon} never reaches picocli ({@link #main}), so here it is misplaced. */
    @CommandLine.Option(
            names = DaemonClient.OPTION,
            description = "first on the line: run the render command in a background JVM that stays warm between"
                    + " commands, so that renders after the first skip the JIT's start (started on first use; ends"
                    + " after 10 idle minutes or on --daemon stop; docs/CLI.md)")
    void daemon(boolean unused) {
        throw new CommandLine.ParameterException(
                spec.commandLine(),
                DaemonClient.OPTION + " must be the first argument of the raytracer command (" + DaemonClient.OPTION
                        + " render scene.json ...); from Java, render in your own JVM instead");
    }

    /** Without a subcommand: the usage, and exit code 2 (nothing was done). */
    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required, e.g. render");
    }

    /**
     * Runs the command line and exits with its code when it is not 0. With {@code --daemon} first, the command runs
     * in the render daemon ({@link DaemonClient}), and this JVM loads neither the renderer nor Jackson.
     *
     * @param args the command-line arguments
     */
    public static void main(String[] args) {
        int code = args.length > 0 && args[0].equals(DaemonClient.OPTION)
                ? DaemonClient.main(List.of(args).subList(1, args.length))
                : run(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true));
        // Exit only on failure: on success, returning lets `mvn exec:java` finish normally.
        if (code != ExitCodes.OK) System.exit(code);
    }

    /**
     * Runs the command line and returns its exit code; {@code out} and {@code err} receive its output.
     *
     * @param args the command-line arguments
     * @param out where normal output goes
     * @param err where errors go
     * @return the exit code, one of {@link ExitCodes}
     */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return commandLine(out, err).execute(args);
    }

    /**
     * The configured command line, for tests and for embedding.
     *
     * @param out where normal output goes
     * @param err where errors go
     * @return a new command line with the subcommands, configured as by {@link #configure}
     */
    public static CommandLine commandLine(PrintWriter out, PrintWriter err) {
        return configure(new CommandLine(new RaytracerCli()), out, err);
    }

    /**
     * Gives another command line (e.g. the Spark jobs' in src/spark) the same behaviour as this one: output to
     * {@code out} and {@code err}, enum values in any case, and the same error reporting and exit codes (bad
     * input: one {@code error: ...} line and exit 2; any other failure: exit 1).
     *
     * @param cl the command line to configure
     * @param out where normal output goes
     * @param err where errors go
     * @return {@code cl}, configured
     */
    public static CommandLine configure(CommandLine cl, PrintWriter out, PrintWriter err) {
        cl.setOut(out);
        cl.setErr(err);
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.setExecutionExceptionHandler((e, commandLine, parseResult) -> {
            PrintWriter w = commandLine.getErr();
            if (e instanceof SceneFileException || e instanceof BadInputException) {
                w.println("error: " + primitives.Printable.message(e.getMessage()));
                w.flush();
                return ExitCodes.BAD_INPUT;
            }
            w.println("render failed: " + primitives.Printable.message(e.toString()));
            StackTraceElement[] trace = e.getStackTrace();
            for (int i = 0; i < Math.min(trace.length, 8); i++) w.println("    at " + trace[i]);
            w.flush();
            return ExitCodes.RENDER_FAILED;
        });
        return cl;
    }
}
