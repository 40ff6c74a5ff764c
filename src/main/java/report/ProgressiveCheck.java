package report;

import java.io.PrintStream;
import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
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
     * @param lowest the lowest of the repeated renders' measured RMSEs
     * @param highest the highest of them
     * @param renders how many renders were made of this request
     * @param seconds the render's wall time
     * @param samples the camera samples it took
     * @param fixedRmse for a budget: the RMSE of the fixed HALTON render whose time set the budget, else 0
     * @param referenceError the reference's own RMSE ({@link Reference}), part of every measured one
     */
    record Row(
            String experiment,
            String asked,
            double target,
            double budget,
            double predicted,
            double measured,
            double lowest,
            double highest,
            int renders,
            double seconds,
            long samples,
            double fixedRmse,
            double referenceError) {
        /**
         * Whether a target-error render missed its target by more than the tolerance, measured against the reference
         * as it is (its own error included: the stricter test).
         */
        boolean failed() {
            return target > 0 && measured > (1 + TOLERANCE) * target;
        }

        /** The measured RMSE less the reference's own: an estimate of the error against the true image. */
        double measuredLessReference() {
            return Reference.without(measured, referenceError);
        }
    }

    /**
     * Runs the check: renders per target, renders per budget (each budget the time of a fixed HALTON render whose
     * error is given beside it). Measured in a JVM as warm as the fixed renders': untimed rounds of the requests
     * first, until the JIT is quiet ({@link #warmUp}; a short budget is otherwise spent partly by the JIT compiling the
     * progressive path, which the fixed renders before it did not run), then {@code repeats} renders per row. A
     * target's samples and image do not depend on time, so its row keeps the median time; a budget's samples do, so
     * its row keeps the render of median error, and the range of the errors is kept beside it. A render slower than
     * {@link AccuracyReport#SLOW_RENDER_SECONDS} is not repeated.
     *
     * <p>Each budgeted render is given the time of the fixed render timed just before it, not the fixed renders'
     * median from earlier in the report: the machine's speed drifts, and a budget timed in a slower minute than its
     * fixed render buys fewer samples for a reason that has nothing to do with sampling (soft shadows' 0.05 s budget
     * once spread from RMSE 2.03 to 2.98 over three renders).
     */
    static List<Row> run(
            Experiment experiment,
            ImageWriter reference,
            double referenceError,
            int width,
            int height,
            double[] targets,
            List<Measurement> budgets,
            int repeats,
            PrintStream log) {
        List<Request> requests = new ArrayList<>();
        for (double target : targets) requests.add(new Request(target, null));
        for (Measurement fixed : budgets) requests.add(new Request(0, fixed));
        int rounds = warmUp(requests, request -> render(experiment, reference, referenceError, width, height, request));
        log.printf(Locale.ROOT, "  progressive warm-up: %d round(s)%n", rounds);
        List<Row> rows = new ArrayList<>();
        for (Request request : requests) {
            List<Row> runs = new ArrayList<>();
            do {
                runs.add(render(experiment, reference, referenceError, width, height, request));
            } while (runs.size() < repeats && runs.get(0).seconds() <= AccuracyReport.SLOW_RENDER_SECONDS);
            rows.add(median(runs));
        }
        return rows;
    }

    /** Rounds of warm-up at most, should the JIT never fall quiet (a busy machine's other JVMs do not count). */
    static final int MAX_WARM_UP_ROUNDS = 12;

    /** A render slower than this is warmed up in the first round only: the renders before it warm its path. */
    static final double WARM_UP_ONCE_SECONDS = 2;

    /** The JIT is quiet once it compiles for less than this share of a round's wall time. */
    static final double QUIET_JIT = 0.02;

    /**
     * Warm-up, untimed: rounds of every request (a slow one in the first round only), until the JIT compiles for less
     * than {@link #QUIET_JIT} of a round's time, so that the timed renders run compiled code, as the fixed renders
     * before them did. One round was not enough: over a time budget's first 20 renders of the anti-aliasing
     * experiment (0.09 s each), the JIT compiled for 40-165 ms per render, on one of the machine's two cores, and
     * the renders took 153,000-863,000 samples; then 0-10 ms and 551,000-1,007,000 (27 Nov). Where the JVM cannot
     * tell its compilation time, three rounds.
     *
     * @return the rounds rendered
     */
    static int warmUp(List<Request> requests, Function<Request, Row> render) {
        CompilationMXBean jit = ManagementFactory.getCompilationMXBean();
        boolean timed = jit != null && jit.isCompilationTimeMonitoringSupported();
        List<Request> again = new ArrayList<>();
        for (int round = 1; ; round++) {
            long compiled = timed ? jit.getTotalCompilationTime() : 0, start = System.nanoTime();
            for (Request request : round == 1 ? requests : again) {
                Row row = render.apply(request);
                if (round == 1 && row.seconds() <= WARM_UP_ONCE_SECONDS) again.add(request);
            }
            double millis = (System.nanoTime() - start) * 1e-6;
            boolean quiet = timed ? jit.getTotalCompilationTime() - compiled < QUIET_JIT * millis : round == 3;
            if (quiet || again.isEmpty() || round == MAX_WARM_UP_ROUNDS) return round;
        }
    }

    /**
     * Of repeated renders of one request, the one of median error (a time budget's error varies with the machine's
     * speed), with the median time (a target's does not: only its time varies) and the errors' range.
     */
    static Row median(List<Row> runs) {
        List<Row> byError = new ArrayList<>(runs);
        byError.sort(Comparator.comparingDouble(Row::measured));
        double[] seconds = runs.stream().mapToDouble(Row::seconds).sorted().toArray();
        Row m = byError.get(runs.size() / 2);
        double time = m.target() > 0 ? seconds[seconds.length / 2] : m.seconds();
        return new Row(
                m.experiment(),
                m.asked(),
                m.target(),
                m.budget(),
                m.predicted(),
                m.measured(),
                byError.get(0).measured(),
                byError.get(byError.size() - 1).measured(),
                runs.size(),
                time,
                m.samples(),
                m.fixedRmse(),
                m.referenceError());
    }

    /**
     * What a row asks: a target RMSE, or (with target 0) a time budget, the time of the fixed HALTON render
     * {@code fixed} timed just before each of its renders.
     */
    record Request(double target, Measurement fixed) {}

    private static Row render(
            Experiment experiment,
            ImageWriter reference,
            double referenceError,
            int width,
            int height,
            Request request) {
        Measurement fixed = request.fixed();
        ProgressiveSettings settings;
        if (fixed == null) {
            settings = ProgressiveSettings.targetError(request.target());
        } else {
            // The budget is the fixed render's time in this minute (see run).
            Camera timed = experiment
                    .camera(Variant.HALTON, fixed.samples(), width, height)
                    .renderImage();
            settings = ProgressiveSettings.timeBudget(timed.getLastStatistics().wallSeconds());
        }
        Camera camera =
                experiment.progressive(width, height).setProgressive(settings).renderImage();
        ProgressiveReport report = camera.getLastProgressiveReport();
        double measured = ImageError.between(camera.getImage(), reference).rmse();
        String asked = settings.targetError() > 0
                ? String.format(Locale.ROOT, "RMSE %.3g", settings.targetError())
                : String.format(Locale.ROOT, "%.3g s", settings.timeBudgetSeconds());
        return new Row(
                experiment.slug(),
                asked,
                settings.targetError(),
                settings.timeBudgetSeconds(),
                report.predictedError(),
                measured,
                measured,
                measured,
                1,
                camera.getLastStatistics().wallSeconds(),
                report.samples(),
                fixed == null ? 0 : fixed.rmse(),
                referenceError);
    }

    /** The Markdown table of the rows. */
    static String table(List<Row> rows) {
        StringBuilder s = new StringBuilder(
                "| asked | predicted RMSE | measured RMSE | less the reference's own | time (s) | samples |"
                        + " fixed HALTON in that time | budget renders' RMSEs |\n"
                        + "|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (Row r : rows) {
            s.append(String.format(
                    Locale.ROOT,
                    "| %s | %.3f | %.3f%s | %.3f | %.3f | %,d | %s | %s |%n",
                    r.asked(),
                    r.predicted(),
                    r.measured(),
                    r.failed() ? " (**more than 25% above the target**)" : "",
                    r.measuredLessReference(),
                    r.seconds(),
                    r.samples(),
                    r.budget() > 0 ? String.format(Locale.ROOT, "RMSE %.3f", r.fixedRmse()) : "",
                    r.budget() > 0 ? range(r) : ""));
        }
        return s.toString();
    }

    /** A budget row's spread: "1.98-2.41 (3 renders)", or its one error. */
    static String range(Row r) {
        return r.renders() > 1
                ? String.format(Locale.ROOT, "%.3f-%.3f (%d renders)", r.lowest(), r.highest(), r.renders())
                : String.format(Locale.ROOT, "%.3f (1 render)", r.measured());
    }
}
