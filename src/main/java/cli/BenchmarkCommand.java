package cli;

import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/**
 * {@code raytracer benchmark bvh|planning|render|effects|instancing|povray [args]}: the benchmarks, each printing a Markdown table.
 * {@code bvh} takes {@code runs=N threads=1,2 only=workload,...} (see docs/BENCHMARKS.md; it wants a large heap,
 * so {@code mvn -Pbenchmark} runs it in a JVM of its own); {@code planning} takes the number of runs; {@code render}
 * takes {@code --runs N --threads 1,2 --only NAME --csv FILE --images DIR --baseline FILE --light-cutoff STEPS};
 * {@code effects} takes runs, width and height; {@code instancing} takes runs and the grove's side.
 */
@Command(
        name = "benchmark",
        mixinStandardHelpOptions = true,
        subcommands = RenderBenchmarkCommand.class,
        description = "Runs a benchmark: bvh (BVH on/off, threads), planning (effect planning on/off), "
                + "render (real renders: time, rays, allocation; --baseline FILE compares), "
                + "effects (time factor of each sampled effect), "
                + "instancing (instances vs copies: memory, build, render), "
                + "povray (the soft-shadow comparison with POV-Ray; needs povray).")
public final class BenchmarkCommand implements Callable<Integer> {
    @Parameters(
            index = "0",
            arity = "0..1",
            paramLabel = "bvh|planning|effects|instancing|povray",
            description = "which benchmark (render is a subcommand with options of its own)")
    private String which;

    @Parameters(index = "1..*", paramLabel = "args", description = "arguments of that benchmark")
    private List<String> args = List.of();

    @Override
    public Integer call() throws BadInputException {
        if (which == null) {
            throw new BadInputException(
                    "benchmark: which benchmark? allowed: bvh, planning, render, effects, instancing, povray");
        }
        String[] rest = args.toArray(new String[0]);
        try {
            switch (which) {
                case "bvh" -> benchmark.BvhBenchmark.main(rest);
                case "planning" -> benchmark.PlanningBenchmark.main(rest);
                case "effects" -> app.FeatureGallery.main(rest);
                case "instancing" -> benchmark.InstancingBenchmark.main(rest);
                case "povray" -> povray(rest);
                default ->
                    throw new BadInputException("benchmark: unknown benchmark '" + which
                            + "'; allowed: bvh, planning, render, effects, instancing, povray");
            }
        } catch (NumberFormatException e) {
            // "For input string: \"many\"": the value alone, as the user wrote it.
            String message = String.valueOf(e.getMessage());
            int quote = message.indexOf('"');
            String value =
                    quote >= 0 ? message.substring(quote + 1, Math.max(quote + 1, message.lastIndexOf('"'))) : "";
            throw new BadInputException("benchmark " + which + ": '" + value + "' is not an integer");
        } catch (IllegalArgumentException e) {
            throw new BadInputException("benchmark " + which + ": " + e.getMessage());
        }
        return ExitCodes.OK;
    }

    /** The POV-Ray comparison; a missing povray or an unreadable image is a failure with the reason. */
    private static void povray(String[] args) {
        try {
            benchmark.PovRayComparison.main(args);
        } catch (RuntimeException e) {
            throw e;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("benchmark povray: interrupted", e);
        } catch (Exception e) {
            throw new IllegalStateException("benchmark povray: " + e.getMessage(), e);
        }
    }
}
