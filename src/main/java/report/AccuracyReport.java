package report;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;
import primitives.Limits;
import renderer.AtomicFile;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayCounters;

/**
 * What accuracy costs in time: for each sampled effect, renders a converged reference, then every variant
 * (pattern, fixed or adaptive) at every sample count, measuring render time (median of repeats), rays by kind and
 * the error against the reference. Writes per experiment a CSV table, a log-log chart of error against samples and
 * against time with fitted convergence slopes, and enlarged crops; and one Markdown report with every table.
 *
 * <p>Run: {@code mvn -q compile exec:java -Dexec.mainClass=report.AccuracyReport}; options as
 * {@code -Dexec.args="--size 160x120 --counts 1,4,16,64,256 --repeats 3 --out images"}.
 */
public final class AccuracyReport {

    /**
     * What to run and where to write it.
     *
     * @param width image width in pixels, at least 8
     * @param height image height in pixels, at least 8
     * @param counts the sample counts to measure, at least two
     * @param repeats timed renders per measurement (the median is kept), at least 1
     * @param out the folder the report, tables, charts and crops are written to
     * @param experiments the experiments to run, in order
     */
    public record Options(int width, int height, int[] counts, int repeats, Path out, List<Experiment> experiments) {
        /**
         * The defaults: 160 x 120 pixels, counts 1, 4, 16, 64 and 256, 3 repeats, folder {@code images}, the standard
         * experiments.
         *
         * @return the default options
         */
        public static Options defaults() {
            return new Options(160, 120, new int[] {1, 4, 16, 64, 256}, 3, Path.of("images"), standardExperiments());
        }
    }

    /**
     * The experiments the report runs by default.
     *
     * @return the anti-aliasing, soft shadow, depth of field, glossy and street experiments, in that order
     */
    public static List<Experiment> standardExperiments() {
        return List.of(
                new AntiAliasingExperiment(),
                new SoftShadowExperiment(),
                new DepthOfFieldExperiment(),
                new GlossyExperiment(),
                new StreetExperiment());
    }

    private AccuracyReport() {}

    /**
     * Runs the report with the options in {@code args} and prints where it was written.
     *
     * @param args the options: {@code --size WxH}, {@code --counts n1,n2,...}, {@code --repeats N}, {@code --out
     *     folder}, {@code --only slug1,slug2}
     */
    public static void main(String[] args) {
        Options options = parse(args);
        List<Measurement> all = run(options, System.out);
        System.out.println("wrote " + options.out().resolve("accuracy").resolve("report.md") + " (" + all.size()
                + " measurements)");
    }

    /** Largest image side and most repeats the report takes (its references render at far more samples). */
    static final int MAX_SIDE = 4096, MAX_REPEATS = 1000;

    /**
     * Options from command-line arguments; an unknown or malformed option is an IllegalArgumentException.
     *
     * @param args the options: {@code --size WxH}, {@code --counts n1,n2,...}, {@code --repeats N}, {@code --out
     *     folder}, {@code --only slug1,slug2}
     * @return the defaults with the given options replaced
     * @throws IllegalArgumentException if an option is unknown or lacks its value, or a size is outside 8 x 8 to
     *     4096 x 4096, repeats outside 1 to 1000, a count outside 1 to 1048576, or fewer than two counts are given
     */
    public static Options parse(String[] args) {
        Options o = Options.defaults();
        int width = o.width(), height = o.height(), repeats = o.repeats();
        int[] counts = o.counts();
        Path out = o.out();
        List<Experiment> experiments = o.experiments();
        for (int i = 0; i < args.length; i++) {
            String value = i + 1 < args.length ? args[i + 1] : null;
            switch (args[i]) {
                case "--size" -> {
                    String[] wh = require(value, "--size").split("x", -1);
                    if (wh.length != 2) throw new IllegalArgumentException("--size must be WxH, e.g. 160x120");
                    width = Integer.parseInt(wh[0]);
                    height = Integer.parseInt(wh[1]);
                    i++;
                }
                case "--counts" -> {
                    counts = Arrays.stream(require(value, "--counts").split(","))
                            .mapToInt(Integer::parseInt)
                            .toArray();
                    i++;
                }
                case "--repeats" -> {
                    repeats = Integer.parseInt(require(value, "--repeats"));
                    i++;
                }
                case "--out" -> {
                    out = Path.of(require(value, "--out"));
                    i++;
                }
                case "--only" -> {
                    experiments = only(require(value, "--only"));
                    i++;
                }
                default ->
                    throw new IllegalArgumentException("unknown option '" + args[i]
                            + "'; allowed: --size WxH, --counts n1,n2,..., --repeats N, --out folder");
            }
        }
        if (width < 8 || height < 8 || width > MAX_SIDE || height > MAX_SIDE) {
            throw new IllegalArgumentException(
                    "--size must be from 8x8 to " + MAX_SIDE + "x" + MAX_SIDE + ", but was " + width + "x" + height);
        }
        if (repeats < 1 || repeats > MAX_REPEATS) {
            throw new IllegalArgumentException("--repeats must be in [1, " + MAX_REPEATS + "], but was " + repeats);
        }
        if (counts.length < 2) throw new IllegalArgumentException("--counts needs two or more sample counts");
        for (int n : counts) {
            if (n < 1 || n > Limits.MAX_SAMPLES) {
                throw new IllegalArgumentException(
                        "--counts: each must be in [1, " + Limits.MAX_SAMPLES + "], but was " + n);
            }
        }
        return new Options(width, height, counts, repeats, out, experiments);
    }

    /** The standard experiments named by their slugs, in the report's order; an unknown slug is rejected. */
    static List<Experiment> only(String slugs) {
        List<Experiment> all = standardExperiments();
        List<String> known = all.stream().map(Experiment::slug).toList();
        List<String> wanted = Arrays.asList(slugs.split(","));
        for (String slug : wanted) {
            if (!known.contains(slug)) {
                throw new IllegalArgumentException(
                        "unknown experiment '" + slug + "' in --only; allowed: " + String.join(", ", known));
            }
        }
        return all.stream().filter(e -> wanted.contains(e.slug())).toList();
    }

    private static String require(String value, String option) {
        if (value == null) throw new IllegalArgumentException(option + " needs a value");
        return value;
    }

    /**
     * Runs every experiment of {@code options}, writes the outputs, returns all measurements.
     *
     * @param options what to run and where to write it
     * @param log where progress lines are printed
     * @return every measurement of every experiment, in the order taken
     */
    public static List<Measurement> run(Options options, java.io.PrintStream log) {
        Path folder = options.out().resolve("accuracy");
        List<Measurement> all = new ArrayList<>();
        List<ProgressiveCheck.Row> progressive = new ArrayList<>();
        StringBuilder markdown = new StringBuilder();
        markdown.append(String.format(
                Locale.ROOT,
                "# What accuracy costs%n%nImages %d x %d unless stated, %d render thread(s), time = median of %d runs "
                        + "(renders over %.0f s run once).%n"
                        + "Error = RMSE over pixels and channels (0..255, clamped as displayed) and the 99th "
                        + "percentile of the per-pixel error, against a converged reference.%n",
                options.width(),
                options.height(),
                Runtime.getRuntime().availableProcessors(),
                options.repeats(),
                SLOW_RENDER_SECONDS));
        for (Experiment experiment : options.experiments()) {
            int[] size = experiment.size(options.width(), options.height());
            int w = size[0], h = size[1];
            int[] counts = experiment.counts(options.counts());
            log.println("== " + experiment.name() + " (" + w + " x " + h + ")");
            Reference rendered = Reference.render(experiment, w, h);
            ImageWriter reference = rendered.image();
            double referenceSeconds = rendered.seconds(), referenceError = rendered.ownError();
            writePng(folder.resolve(experiment.slug() + "-reference.png"), reference.toBufferedImage());
            log.printf(
                    Locale.ROOT, "  reference: %.2f s, its own error about %.3f%n", referenceSeconds, referenceError);
            experiment.camera(experiment.variants().get(0), counts[1], w, h).renderImage(); // warm-up
            Map<String, List<Measurement>> byVariant = new LinkedHashMap<>();
            List<Variant> variants = experiment.variants();
            ImageWriter[][] crops = new ImageWriter[variants.size()][counts.length + 1];
            for (int v = 0; v < variants.size(); v++) {
                Variant variant = variants.get(v);
                List<Measurement> series = new ArrayList<>();
                for (int c = 0; c < counts.length; c++) {
                    int n = counts[c];
                    Timed t = time(experiment, variant, n, w, h, options.repeats());
                    ImageError error = ImageError.between(t.image, reference);
                    RayCounters rays = t.rays;
                    Measurement m = new Measurement(
                            experiment.slug(),
                            variant.label(),
                            n,
                            t.seconds,
                            rays.camera,
                            rays.shadow,
                            rays.reflection + rays.refraction,
                            error.rmse(),
                            error.p99());
                    series.add(m);
                    crops[v][c] = t.image;
                    log.printf(
                            Locale.ROOT,
                            "  %-18s %4d: %7.3f s  rmse %7.3f  p99 %7.3f%n",
                            variant.label(),
                            n,
                            m.seconds(),
                            m.rmse(),
                            m.p99());
                }
                crops[v][counts.length] = reference;
                byVariant.put(variant.label(), series);
                all.addAll(series);
            }
            write(folder.resolve(experiment.slug() + ".csv"), csv(byVariant));
            writePng(
                    options.out().resolve("accuracy-" + experiment.slug() + ".png"),
                    Charts.convergence(experiment.name(), experiment.sampleUnit(), byVariant));
            List<String> columns = new ArrayList<>();
            for (int n : counts) columns.add(n + (n == 1 ? " sample" : " samples"));
            columns.add("reference");
            writePng(
                    options.out().resolve("accuracy-" + experiment.slug() + "-crops.png"),
                    Crops.grid(variants.stream().map(Variant::label).toList(), columns, crops, experiment.crop()));
            markdown.append(section(experiment, byVariant, referenceSeconds, referenceError, w, h));
            List<ProgressiveCheck.Row> checks = ProgressiveCheck.run(
                    experiment,
                    reference,
                    referenceError,
                    w,
                    h,
                    PROGRESSIVE_TARGETS,
                    budgets(byVariant),
                    options.repeats(),
                    log);
            for (ProgressiveCheck.Row r : checks) {
                log.printf(
                        Locale.ROOT,
                        "  progressive %-10s: %7.3f s  predicted %7.3f  rmse %7.3f%s%s%n",
                        r.asked(),
                        r.seconds(),
                        r.predicted(),
                        r.measured(),
                        r.budget() > 0 ? "  (" + ProgressiveCheck.range(r) + ")" : "",
                        r.failed() ? "  MORE THAN 25% ABOVE THE TARGET" : "");
            }
            markdown.append(String.format(
                    Locale.ROOT,
                    "%n### Asked for an error or a time (progressive sampling, HALTON, 2 samples of the effect per"
                            + " camera sample)%n%n%s",
                    ProgressiveCheck.table(checks)));
            progressive.addAll(checks);
        }
        if (!progressive.isEmpty()) {
            writePng(options.out().resolve("accuracy-progressive.png"), Charts.predictedVersusMeasured(progressive));
        }
        write(folder.resolve("report.md"), markdown.toString());
        return all;
    }

    /** The target RMSEs every experiment's progressive renders are asked for. */
    static final double[] PROGRESSIVE_TARGETS = {4, 2, 1};

    /**
     * The time budgets of the progressive renders: the times of the fixed HALTON renders at the two largest counts
     * measured, so that each budgeted render is compared with the fixed setting that took the same time.
     */
    private static List<Measurement> budgets(Map<String, List<Measurement>> byVariant) {
        List<Measurement> halton = byVariant.get(Variant.HALTON.label());
        if (halton == null || halton.size() < 2) return List.of();
        return halton.subList(halton.size() - 2, halton.size());
    }

    /** A render slower than this is timed once: its time is far above the noise, and repeats would cost minutes. */
    static final double SLOW_RENDER_SECONDS = 5;

    private record Timed(ImageWriter image, double seconds, RayCounters rays) {}

    private static Timed time(Experiment experiment, Variant variant, int samples, int w, int h, int repeats) {
        double[] seconds = new double[repeats];
        Camera camera = null;
        int runs = 0;
        while (runs < repeats) {
            camera = experiment.camera(variant, samples, w, h).renderImage();
            seconds[runs++] = camera.getLastStatistics().wallSeconds();
            if (seconds[0] > SLOW_RENDER_SECONDS) break;
        }
        Arrays.sort(seconds, 0, runs);
        return new Timed(
                camera.getImage(), seconds[runs / 2], camera.getLastStatistics().rays());
    }

    private static String csv(Map<String, List<Measurement>> byVariant) {
        StringBuilder s = new StringBuilder(Measurement.CSV_HEADER).append('\n');
        byVariant.values().forEach(list -> list.forEach(m -> s.append(m.csv()).append('\n')));
        return s.toString();
    }

    /** The Markdown section of one experiment: the measurements, and the fitted slopes per variant. */
    static String section(
            Experiment experiment,
            Map<String, List<Measurement>> byVariant,
            double referenceSeconds,
            double referenceError,
            int width,
            int height) {
        StringBuilder s = new StringBuilder();
        s.append(String.format(
                Locale.ROOT,
                "%n## %s (%s)%n%n%d x %d pixels. Reference: the mean of two renders with different seeds, %.2f s;"
                        + " its own RMSE about %.3f (half the two renders' difference), part of every error below.%n%n",
                experiment.name(),
                experiment.sampleUnit(),
                width,
                height,
                referenceSeconds,
                referenceError));
        if (!experiment.description().isEmpty())
            s.append(experiment.description()).append("\n\n");
        s.append("| variant | samples | time (s) | rays | RMSE | p99 |\n|---|---:|---:|---:|---:|---:|\n");
        byVariant
                .values()
                .forEach(list -> list.forEach(m -> s.append(String.format(
                        Locale.ROOT,
                        "| %s | %d | %.3f | %,d | %.3f | %.3f |%n",
                        m.variant(),
                        m.samples(),
                        m.seconds(),
                        m.rays(),
                        m.rmse(),
                        m.p99()))));
        s.append("\n| variant | slope vs samples | slope vs time | time to halve the error |\n|---|---:|---:|---:|\n");
        for (Map.Entry<String, List<Measurement>> e : byVariant.entrySet()) {
            List<Measurement> m =
                    e.getValue().subList(1, e.getValue().size()); // every pattern's 1 sample is the centre
            ConvergenceFit bySamples = ConvergenceFit.of(
                    m.stream().mapToDouble(Measurement::samples).toArray(),
                    m.stream().mapToDouble(Measurement::rmse).toArray());
            ConvergenceFit byTime = ConvergenceFit.of(
                    m.stream().mapToDouble(Measurement::seconds).toArray(),
                    m.stream().mapToDouble(Measurement::rmse).toArray());
            s.append(String.format(
                    Locale.ROOT,
                    "| %s | %.2f | %.2f | %s |%n",
                    e.getKey(),
                    bySamples.slope(),
                    byTime.slope(),
                    halvingFactor(byTime.factorToHalveError())));
        }
        s.append(lowDiscrepancyVersusRandom(byVariant));
        String verdict = experiment.verdict(byVariant);
        if (!verdict.isEmpty()) s.append('\n').append(verdict);
        return s.toString();
    }

    /** The time factor that halves the error, or why there is none (an error that does not fall). */
    static String halvingFactor(double factor) {
        if (!Double.isFinite(factor) || factor <= 0) return "never: the error does not fall";
        return String.format(Locale.ROOT, "%.1fx", factor);
    }

    /** At how many of the measured counts above one the HALTON pattern had a lower RMSE than RANDOM. */
    static String lowDiscrepancyVersusRandom(Map<String, List<Measurement>> byVariant) {
        List<Measurement> halton = byVariant.get(Variant.HALTON.label()),
                random = byVariant.get(Variant.RANDOM.label());
        if (halton == null || random == null) return "";
        int better = 0, compared = 0;
        StringBuilder ratios = new StringBuilder();
        for (int i = 0; i < Math.min(halton.size(), random.size()); i++) {
            if (halton.get(i).samples() <= 1) continue;
            compared++;
            if (halton.get(i).rmse() < random.get(i).rmse()) better++;
            ratios.append(ratios.length() == 0 ? "" : ", ")
                    .append(String.format(
                            Locale.ROOT,
                            "%d: %.2f",
                            halton.get(i).samples(),
                            halton.get(i).rmse() / random.get(i).rmse()));
        }
        return String.format(
                Locale.ROOT,
                "%nHALTON beats RANDOM at %d of %d sample counts above one (RMSE ratio halton/random by count: %s).%n",
                better,
                compared,
                ratios);
    }

    private static void write(Path file, String text) {
        AtomicFile.write(file, "report file", temp -> Files.writeString(temp, text, StandardCharsets.UTF_8));
    }

    private static void writePng(Path file, BufferedImage image) {
        AtomicFile.write(file, "image", temp -> ImageIO.write(image, "png", temp.toFile()));
    }
}
