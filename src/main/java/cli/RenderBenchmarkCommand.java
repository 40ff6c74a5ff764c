package cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code raytracer benchmark render}: real renders timed, with rays, work and allocation per ray, optionally beside
 * a baseline CSV of another build ({@link benchmark.RenderBenchmark}).
 */
@Command(
        name = "render",
        mixinStandardHelpOptions = true,
        description = "Times real renders (the street with hard lamps and at the main job's settings, the showcase, "
                + "glass and mirror) on 1 and 2 threads: wall and CPU time, rays by kind, M rays per CPU-second, "
                + "nodes and tests per ray, bytes allocated per ray. --baseline compares with a CSV of another build.")
public final class RenderBenchmarkCommand implements Callable<Integer> {
    @Option(names = "--runs", paramLabel = "N", description = "timed renders per row, after a warm-up (default 3)")
    private int runs = 3;

    @Option(names = "--threads", paramLabel = "T,...", split = ",", description = "thread counts (default 1,2)")
    private List<Integer> threads = List.of(1, 2);

    @Option(
            names = "--only",
            paramLabel = "NAME,...",
            split = ",",
            description = "only these scenes: street-hard, street-main, showcase, glass-and-mirror")
    private List<String> only = List.of();

    @Option(names = "--csv", paramLabel = "FILE", description = "save the figures as CSV")
    private Path csv;

    @Option(names = "--images", paramLabel = "DIR", description = "save each row's 8-bit image (compared too)")
    private Path images;

    @Option(names = "--baseline", paramLabel = "FILE", description = "a CSV of another build to compare with")
    private Path baseline;

    @Option(
            names = "--light-cutoff",
            paramLabel = "STEPS",
            description = "render with this light cut-off in display steps (0 = exact; default: the scene's)")
    private Double lightCutoff;

    @Override
    public Integer call() throws BadInputException, IOException {
        List<String> args = new ArrayList<>(List.of("--runs", Integer.toString(runs)));
        args.add("--threads");
        args.add(String.join(",", threads.stream().map(String::valueOf).toList()));
        if (!only.isEmpty()) {
            args.add("--only");
            args.add(String.join(",", only));
        }
        if (csv != null) args.addAll(List.of("--csv", csv.toString()));
        if (images != null) args.addAll(List.of("--images", images.toString()));
        if (baseline != null) args.addAll(List.of("--baseline", baseline.toString()));
        if (lightCutoff != null) args.addAll(List.of("--light-cutoff", lightCutoff.toString()));
        try {
            benchmark.RenderBenchmark.main(args.toArray(new String[0]));
        } catch (IllegalArgumentException e) {
            throw new BadInputException("benchmark render: " + e.getMessage());
        }
        return ExitCodes.OK;
    }
}
