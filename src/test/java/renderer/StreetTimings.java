package renderer;

import app.StreetScene;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The timing table of {@link StreetSceneTest}: one row per rendered configuration with its wall and CPU time
 * (medians of the runs), rays by kind and its speed-up over the plain render of the same image size, as Markdown
 * for {@code images/street-timings.md}. CPU time is reported beside wall time because the machines this runs on
 * are often shared: other work stretches the wall time, much less the processor time a render consumes.
 */
final class StreetTimings {
    /** System load averages seen when the measurements started and ended. */
    private static final List<Double> LOADS = new ArrayList<>();

    private StreetTimings() {}

    /**
     * One configuration's measurement.
     *
     * @param label what was switched on
     * @param image the image file written, or "" for an estimate
     * @param seconds median wall time of the runs (extrapolated when {@code estimated})
     * @param cpuSeconds median processor time the JVM consumed during the runs (all threads)
     * @param runs renders timed
     * @param statistics rays and work of the last run
     * @param estimated whether the row was extrapolated rather than rendered
     */
    record Row(
            String label,
            String image,
            int width,
            int height,
            double seconds,
            double cpuSeconds,
            int runs,
            RenderStatistics statistics,
            boolean estimated) {}

    /** CPU time consumed so far by this JVM (all threads), in nanoseconds. */
    static long processCpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    /** Notes the system's one-minute load average, reported with the table. */
    static void recordLoad() {
        LOADS.add(ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
    }

    /** The median of the first {@code n} values. */
    static double median(double[] values, int n) {
        double[] sorted = Arrays.copyOf(values, n);
        Arrays.sort(sorted);
        return sorted[n / 2];
    }

    /** A row for a configuration costing {@code factor} times {@code base}: rays and times scaled, not rendered. */
    static Row estimate(String label, Row base, int factor) {
        RayCounters rays = new RayCounters();
        for (int i = 0; i < factor; i++) rays.add(base.statistics().rays());
        RenderStatistics s = base.statistics();
        RenderStatistics scaled = new RenderStatistics(
                s.wallSeconds() * factor,
                s.preparationSeconds(),
                s.threads(),
                s.pixels(),
                rays,
                s.nodeVisits() * factor,
                s.primitiveTests() * factor,
                s.plan());
        return new Row(
                label,
                "",
                base.width(),
                base.height(),
                base.seconds() * factor,
                base.cpuSeconds() * factor,
                0,
                scaled,
                true);
    }

    /** The Markdown report: the configuration of the run, then the table. */
    static String markdown(StreetQuality quality, StreetScene street, List<Row> rows) {
        StringBuilder s = new StringBuilder();
        s.append("# Street scene: what each feature costs\n\n");
        s.append(String.format(
                Locale.ROOT,
                "Quality `%s`: %d x %d pixels, anti-aliasing %d samples per pixel (GRID), soft shadows %d rays per"
                        + " lamp (radius 10); %,d primitives, %d lights; %d processor(s), Java %s on %s.%n%n",
                quality.name(),
                quality.width(),
                quality.height(),
                quality.aaSamples(),
                quality.shadowSamples(),
                street.primitiveCount(),
                street.scene().lights.size(),
                Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"),
                System.getProperty("os.name")));
        s.append("Command: `mvn test -Dtest=StreetSceneTest")
                .append(quality == StreetQuality.FULL ? " -Dstreet.quality=full" : "")
                .append(String.format(
                        Locale.ROOT,
                        "`. Time is the median wall time of the runs (renders under %.0f s are repeated three times),"
                                + " CPU the processor time the render consumed on all threads; speed-up is the plain"
                                + " render's wall time (same image size) divided by this one's. The machine was shared"
                                + " (load average %s on %d processors during the run), so wall times and the thread"
                                + " speed-up are indicative; CPU times are steadier.%n%n",
                        quality.cheapSeconds(),
                        loads(),
                        Runtime.getRuntime().availableProcessors()));
        s.append("| configuration | image | size | time (s) | CPU (s) | runs | camera rays | shadow rays |"
                + " reflection rays | refraction rays | M rays per CPU s | speed-up vs plain |\n");
        s.append("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (Row row : rows) {
            Row base = baseline(rows, row);
            RayCounters r = row.statistics().rays();
            double speedUp = base.seconds() / row.seconds();
            String approx = row.estimated() ? "~" : "";
            s.append(String.format(
                    Locale.ROOT,
                    "| %s | %s | %d x %d | %s%.2f | %s%.2f | %s | %,d | %,d | %,d | %,d | %.2f | %s |%n",
                    row.label(),
                    row.image().isEmpty() ? "-" : "`" + row.image() + "`",
                    row.width(),
                    row.height(),
                    approx,
                    row.seconds(),
                    approx,
                    row.cpuSeconds(),
                    row.estimated() ? "-" : Integer.toString(row.runs()),
                    r.camera,
                    r.shadow,
                    r.reflection,
                    r.refraction,
                    r.total() / row.cpuSeconds() * 1e-6,
                    speedUp >= 0.1
                            ? String.format(Locale.ROOT, "%.2fx", speedUp)
                            : String.format(Locale.ROOT, "1/%.0f", 1 / speedUp)));
        }
        return s.toString();
    }

    private static String loads() {
        StringBuilder s = new StringBuilder();
        for (double load : LOADS) {
            s.append(s.length() == 0 ? "" : " to ").append(String.format(Locale.ROOT, "%.1f", load));
        }
        return s.toString();
    }

    /** The first row (the plain render) of the same image size. */
    private static Row baseline(List<Row> rows, Row row) {
        for (Row r : rows) if (r.width() == row.width() && r.height() == row.height()) return r;
        return row;
    }

    /** Writes the report to {@code images/street-timings.md} (through a temporary file, never half-written). */
    static void write(String markdown) {
        Path file = Path.of("images", "street-timings.md");
        try {
            Files.createDirectories(file.getParent());
            Path temp = Files.createTempFile(file.getParent(), ".street-timings", ".tmp");
            Files.writeString(temp, markdown);
            Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file, e);
        }
    }
}
