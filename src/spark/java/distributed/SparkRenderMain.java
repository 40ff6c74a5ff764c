package distributed;

import cli.ExitCodes;
import cli.RaytracerCli;
import cli.VersionProvider;
import java.io.PrintWriter;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The Spark jobs' command line, the main class for spark-submit (docs/SPARK.md):
 * {@code raytracer-spark tiles scene.json} renders a still as tiles, {@code raytracer-spark frames scene.json
 * --path path.json} the frames of a camera path. Errors and exit codes are the {@code raytracer} CLI's.
 */
@Command(
        name = "raytracer-spark",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Renders JSON scene files on Apache Spark: a still split into tiles, or the frames of a camera"
                + " path.",
        subcommands = {TilesCommand.class, FramesCommand.class, CommandLine.HelpCommand.class},
        exitCodeOnInvalidInput = ExitCodes.BAD_INPUT,
        exitCodeOnExecutionException = ExitCodes.RENDER_FAILED)
public final class SparkRenderMain implements Runnable {
    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    /** Without a subcommand: the usage, and exit code 2 (nothing was done). */
    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required: tiles or frames");
    }

    public static void main(String[] args) {
        int code = run(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true));
        if (code != ExitCodes.OK) System.exit(code);
    }

    /** Runs the command line and returns its exit code; {@code out} and {@code err} receive its output. */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return RaytracerCli.configure(new CommandLine(new SparkRenderMain()), out, err)
                .execute(args);
    }
}
