package cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import report.AccuracyReport;

/**
 * {@code raytracer report [--size WxH] [--counts 1,4,16,64,256] [--repeats N] [--only slug,...] [--out folder]}: the accuracy
 * report (error against time for every sampled effect), see {@link AccuracyReport}.
 */
@Command(
        name = "report",
        mixinStandardHelpOptions = true,
        description = "Measures what accuracy costs in time for every sampled effect: CSV, Markdown, charts, crops.")
public final class ReportCommand implements Callable<Integer> {
    @Option(names = "--size", paramLabel = "WxH", description = "image size (default ${DEFAULT-VALUE})")
    private String size = "160x120";

    @Option(names = "--counts", paramLabel = "n,n,...", description = "sample counts (default ${DEFAULT-VALUE})")
    private String counts = "1,4,16,64,256";

    @Option(names = "--repeats", description = "timed renders per measurement, median taken (default ${DEFAULT-VALUE})")
    private int repeats = 3;

    @Option(
            names = "--only",
            paramLabel = "slug,...",
            description = "run only these experiments: aa, shadows, dof, glossy, street (default: all)")
    private String only;

    @Option(names = "--out", description = "output folder (default ${DEFAULT-VALUE})")
    private Path out = Path.of("images");

    @Override
    public Integer call() throws BadInputException {
        AccuracyReport.Options options;
        try {
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of(
                    "--size", size, "--counts", counts, "--repeats", String.valueOf(repeats), "--out", out.toString()));
            if (only != null) args.addAll(java.util.List.of("--only", only));
            options = AccuracyReport.parse(args.toArray(String[]::new));
        } catch (IllegalArgumentException e) {
            throw new BadInputException("report: " + e.getMessage() + " (got --size " + size + " --counts " + counts
                    + " --repeats " + repeats + (only == null ? "" : " --only " + only) + ")");
        }
        AccuracyReport.run(options, System.out);
        System.out.println("wrote " + options.out().resolve("accuracy") + " and the charts "
                + options.out().resolve("accuracy-*.png"));
        return ExitCodes.OK;
    }
}
