package cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import robustness.RobustnessReport;

/** {@code raytracer robustness [--probes N]}: the robustness metrics tables, see {@link RobustnessReport}. */
@Command(
        name = "robustness",
        mixinStandardHelpOptions = true,
        description = "Measures acne, leaks, thin gaps, precision and translation invariance (docs/ROBUSTNESS.md).")
public final class RobustnessCommand implements Callable<Integer> {
    @Option(names = "--probes", description = "probes per table cell (default ${DEFAULT-VALUE})")
    private int probes = 20_000;

    @Override
    public Integer call() throws BadInputException {
        if (probes < RobustnessReport.MIN_PROBES || probes > RobustnessReport.MAX_PROBES) {
            throw new BadInputException("robustness: --probes must be in [" + RobustnessReport.MIN_PROBES + ", "
                    + RobustnessReport.MAX_PROBES + "], but was " + probes);
        }
        RobustnessReport.main(new String[] {String.valueOf(probes)});
        return ExitCodes.OK;
    }
}
