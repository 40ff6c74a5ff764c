package report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.ProgressiveReport;
import renderer.ProgressiveSettings;

/**
 * The honesty check of progressive sampling on one experiment: renders asked for a target RMSE and renders given a
 * time budget, each with the error it predicted and the error measured against the experiment's converged
 * reference. A target-error render that lands more than 25% above its target is marked as a failure.
 */
final class ProgressiveCheck {
    /** How far above the target a measured error may lie. */
    static final double TOLERANCE = 0.25;

    private ProgressiveCheck() {}

    /**
     * One progressive render: what was asked, what it predicted and what was measured.
     *
     * @param experiment the experiment's slug
     * @param asked "RMSE 2" or "1.50 s"
     * @param target the target RMSE, or 0 for a time budget
     * @param budget the time budget in seconds, or 0 for a target
     * @param predicted the RMSE the render predicted
     * @param measured the RMSE measured against the reference
     * @param seconds the render's wall time
     * @param samples the camera samples it took
     * @param fixedRmse for a budget: the RMSE of the fixed HALTON render whose time set the budget, else 0
     */
    record Row(
            String experiment,
            String asked,
            double target,
            double budget,
            double predicted,
            double measured,
            double seconds,
            long samples,
            double fixedRmse) {
        /** Whether a target-error render missed its target by more than the tolerance. */
        boolean failed() {
            return target > 0 && measured > (1 + TOLERANCE) * target;
        }
    }

    /**
     * Runs the check: one render per target, one per budget (each budget the time of a fixed HALTON render whose
     * error is given beside it).
     */
    static List<Row> run(
            Experiment experiment,
            ImageWriter reference,
            int width,
            int height,
            double[] targets,
            List<Measurement> budgets) {
        List<Row> rows = new ArrayList<>();
        for (double target : targets) {
            rows.add(render(experiment, reference, width, height, ProgressiveSettings.targetError(target), 0));
        }
        for (Measurement fixed : budgets) {
            rows.add(render(
                    experiment,
                    reference,
                    width,
                    height,
                    ProgressiveSettings.timeBudget(fixed.seconds()),
                    fixed.rmse()));
        }
        return rows;
    }

    private static Row render(
            Experiment experiment,
            ImageWriter reference,
            int width,
            int height,
            ProgressiveSettings settings,
            double fixedRmse) {
        Camera camera =
                experiment.progressive(width, height).setProgressive(settings).renderImage();
        ProgressiveReport report = camera.getLastProgressiveReport();
        double measured = ImageError.between(camera.getImage(), reference).rmse();
        String asked = settings.targetError() > 0
                ? String.format(Locale.ROOT, "RMSE %.3g", settings.targetError())
                : String.format(Locale.ROOT, "%.2f s", settings.timeBudgetSeconds());
        return new Row(
                experiment.slug(),
                asked,
                settings.targetError(),
                settings.timeBudgetSeconds(),
                report.predictedError(),
                measured,
                camera.getLastStatistics().wallSeconds(),
                report.samples(),
                fixedRmse);
    }

    /** The Markdown table of the rows. */
    static String table(List<Row> rows) {
        StringBuilder s = new StringBuilder(
                "| asked | predicted RMSE | measured RMSE | time (s) | samples | fixed HALTON in that time |\n"
                        + "|---|---:|---:|---:|---:|---:|\n");
        for (Row r : rows) {
            s.append(String.format(
                    Locale.ROOT,
                    "| %s | %.3f | %.3f%s | %.3f | %,d | %s |%n",
                    r.asked(),
                    r.predicted(),
                    r.measured(),
                    r.failed() ? " (**more than 25% above the target**)" : "",
                    r.seconds(),
                    r.samples(),
                    r.budget() > 0 ? String.format(Locale.ROOT, "RMSE %.3f", r.fixedRmse()) : ""));
        }
        return s.toString();
    }
}
