package benchmark;

import app.StreetOptions;
import app.StreetScene;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.IntFunction;
import javax.imageio.ImageIO;
import renderer.Camera;
import renderer.RenderSettings;
import renderer.RenderStatistics;
import sceneio.LoadedScene;
import sceneio.SceneLoader;
import sceneio.model.SceneDocument;

/**
 * What a real render costs, scene by scene: the street (hard lamps, and the main job's settings with soft lamps),
 * the showcase and the glass-and-mirror scene at fixed sizes, on 1 and 2 threads, each the median of several
 * renders after a warm-up. Per row: wall time, CPU time of the rendering threads, rays by kind, rays per CPU-second, BVH nodes and primitive
 * tests per ray, and bytes allocated per ray (by the rendering thread, on 1 thread).
 *
 * <p>{@code --csv FILE} saves the figures (and, with {@code --images DIR}, the 8-bit images); {@code --baseline
 * FILE} reads such a file from another build and prints its figures beside these with the ratios, and how many
 * pixels differ from its images, so a speed-up is a ratio measured back to back. The class uses only API that
 * commit 185ecea already had (plus {@code withLightCutoff}, called by reflection where it exists), so the same
 * source compiled against an older build gives that build's baseline (docs/BENCHMARKS.md, "Render").
 */
public final class RenderBenchmark {
    private RenderBenchmark() {}

    /** One row: a scene at a size on a number of threads. */
    private record Scenario(String name, int threads, IntFunction<Camera> camera) {
        String key() {
            return name + "/" + threads + "T";
        }
    }

    /** The figures of one row (the run of median wall time). */
    record Row(
            String key,
            double wallSeconds,
            double cpuSeconds,
            long camera,
            long shadow,
            long reflection,
            long refraction,
            long nodeVisits,
            long primitiveTests,
            double bytesPerRay,
            String image) {
        long rays() {
            return camera + shadow + reflection + refraction;
        }

        double megaRaysPerCpuSecond() {
            return rays() / cpuSeconds * 1e-6;
        }

        String csv() {
            return String.format(
                    Locale.ROOT,
                    "%s,%.4f,%.4f,%d,%d,%d,%d,%d,%d,%.3f,%s",
                    key,
                    wallSeconds,
                    cpuSeconds,
                    camera,
                    shadow,
                    reflection,
                    refraction,
                    nodeVisits,
                    primitiveTests,
                    bytesPerRay,
                    image);
        }

        static Row parse(String line) {
            String[] f = line.split(",", -1);
            return new Row(
                    f[0],
                    Double.parseDouble(f[1]),
                    Double.parseDouble(f[2]),
                    Long.parseLong(f[3]),
                    Long.parseLong(f[4]),
                    Long.parseLong(f[5]),
                    Long.parseLong(f[6]),
                    Long.parseLong(f[7]),
                    Long.parseLong(f[8]),
                    Double.parseDouble(f[9]),
                    f[10]);
        }
    }

    private static final String CSV_HEADER = "scenario,wall_s,cpu_s,camera,shadow,reflection,refraction,"
            + "node_visits,primitive_tests,bytes_per_ray,image";

    /**
     * Runs the benchmark and prints the table, optionally writing a CSV file, the images and a comparison with a
     * baseline.
     *
     * @param args options: {@code --runs N}, {@code --threads 1,2}, {@code --only NAME,...}, {@code --csv FILE}, {@code
     *     --baseline FILE}, {@code --images DIR}, {@code --light-cutoff STEPS}
     * @throws IOException if the baseline cannot be read or the CSV file or an image cannot be written
     * @throws IllegalArgumentException if an option is unknown, lacks its value or is out of range
     */
    public static void main(String[] args) throws IOException {
        int runs = 3;
        List<Integer> threads = List.of(1, 2);
        List<String> only = List.of();
        Path csv = null, baseline = null, images = null;
        Double lightCutoff = null;
        for (int i = 0; i < args.length; i++) {
            String value = i + 1 < args.length ? args[i + 1] : null;
            switch (args[i]) {
                case "--runs" -> runs = Integer.parseInt(require(args[i], value));
                case "--threads" ->
                    threads = Arrays.stream(require(args[i], value).split(","))
                            .map(Integer::parseInt)
                            .toList();
                case "--only" -> only = List.of(require(args[i], value).split(","));
                case "--csv" -> csv = Path.of(require(args[i], value));
                case "--baseline" -> baseline = Path.of(require(args[i], value));
                case "--images" -> images = Path.of(require(args[i], value));
                case "--light-cutoff" -> lightCutoff = Double.parseDouble(require(args[i], value));
                default ->
                    throw new IllegalArgumentException("unknown option '" + args[i]
                            + "'; allowed: --runs N, --threads 1,2, --only NAME,..., --csv FILE, --baseline FILE,"
                            + " --images DIR, --light-cutoff STEPS");
            }
            i++;
        }
        if (runs < 1 || runs > 1000) throw new IllegalArgumentException("--runs must be in [1, 1000], but was " + runs);
        for (int t : threads) {
            if (t < 1 || t > 256) throw new IllegalArgumentException("--threads must be in [1, 256], but was " + t);
        }
        Map<String, Row> before = baseline == null ? Map.of() : read(baseline);
        if (images != null) {
            if (images.toAbsolutePath().toString().contains(",")) {
                throw new IllegalArgumentException("--images " + images + ": the folder's path must not contain ','");
            }
            Path folder = images.toAbsolutePath().normalize();
            for (Row old : before.values()) {
                // This run would overwrite the baseline's images and then find every image identical to itself.
                if (!old.image().isEmpty()
                        && folder.equals(Path.of(old.image())
                                .toAbsolutePath()
                                .normalize()
                                .getParent())) {
                    throw new IllegalArgumentException("--images " + images + ": the baseline " + baseline
                            + " keeps its images in this folder; give this run another one");
                }
            }
            Files.createDirectories(images);
        }

        for (String name : only) {
            if (!SCENES.containsKey(name)) {
                throw new IllegalArgumentException(
                        "--only: unknown scene '" + name + "'; allowed: " + String.join(", ", SCENES.keySet()));
            }
        }
        List<Scenario> scenarios = new ArrayList<>();
        for (String name : SCENES.keySet()) {
            if (!only.isEmpty() && !only.contains(name)) continue;
            for (int t : threads) scenarios.add(new Scenario(name, t, SCENES.get(name)));
        }
        System.out.printf(
                Locale.ROOT,
                "%d run(s) per row after a warm-up, median by wall time; %s%n%n",
                runs,
                baseline == null ? "no baseline" : "baseline " + baseline);
        for (Scenario s : scenarios) {
            if (s.threads() == scenarios.get(0).threads() || scenarios.size() == 1) {
                System.out.println("- " + s.name() + ": " + LEGEND.get(s.name()));
            }
        }
        System.out.println();
        System.out.println("| scene / threads | wall s | CPU s | rays: camera / shadow / reflection / refraction"
                + " | M rays/CPU-s | nodes/ray | tests/ray | bytes/ray | baseline wall s | speed-up (wall)"
                + " | baseline M rays/CPU-s | rays/CPU-s ratio | image vs baseline |");
        System.out.println("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|");
        List<Row> rows = new ArrayList<>();
        for (Scenario s : scenarios) {
            Row row = measure(s, runs, lightCutoff, images);
            rows.add(row);
            Row old = before.get(row.key());
            System.out.printf(
                    Locale.ROOT,
                    "| %s | %.2f | %.2f | %,d / %,d / %,d / %,d | %.2f | %.1f | %.2f | %s | %s | %s | %s | %s | %s |%n",
                    row.key(),
                    row.wallSeconds(),
                    row.cpuSeconds(),
                    row.camera(),
                    row.shadow(),
                    row.reflection(),
                    row.refraction(),
                    row.megaRaysPerCpuSecond(),
                    row.nodeVisits() / (double) row.rays(),
                    row.primitiveTests() / (double) row.rays(),
                    Double.isNaN(row.bytesPerRay()) ? "-" : String.format(Locale.ROOT, "%.2f", row.bytesPerRay()),
                    old == null ? "-" : String.format(Locale.ROOT, "%.2f", old.wallSeconds()),
                    old == null ? "-" : String.format(Locale.ROOT, "%.2fx", old.wallSeconds() / row.wallSeconds()),
                    old == null ? "-" : String.format(Locale.ROOT, "%.2f", old.megaRaysPerCpuSecond()),
                    old == null
                            ? "-"
                            : String.format(
                                    Locale.ROOT, "%.2fx", row.megaRaysPerCpuSecond() / old.megaRaysPerCpuSecond()),
                    old == null ? "-" : compareImages(old.image(), row.image()));
        }
        if (csv != null) {
            List<String> lines = new ArrayList<>();
            lines.add(CSV_HEADER);
            for (Row r : rows) lines.add(r.csv());
            if (csv.getParent() != null) Files.createDirectories(csv.getParent());
            Files.write(csv, lines);
            System.out.println("\nwrote " + csv);
        }
    }

    /** The scenes by short name (for {@code --only} and the CSV), each a camera for a thread count. */
    private static final Map<String, IntFunction<Camera>> SCENES = new LinkedHashMap<>();
    /** What each scene is, for the table's legend. */
    private static final Map<String, String> LEGEND = new LinkedHashMap<>();

    static {
        StreetScene hard = new StreetScene(StreetOptions.HARD);
        scene(
                "street-hard",
                "app.StreetScene with point lamps (hard shadows), no anti-aliasing, 400x250",
                t -> hard.camera(400, 250).setThreads(t).build());
        scene(
                "street-main",
                "scenes/street.json at the main job's settings (16 HALTON camera rays, disk lamps with adaptive"
                        + " shadows of at most 9 rays), 320x200",
                t -> sceneFile("street", 320, 200, t));
        scene(
                "showcase",
                "scenes/showcase.json (adaptive AA, soft lights, glass, mirror), 400x250",
                t -> sceneFile("showcase", 400, 250, t));
        scene(
                "glass-and-mirror",
                "scenes/glass-and-mirror.json (frosted glass, glossy floor, mirror), 480x300",
                t -> sceneFile("glass-and-mirror", 480, 300, t));
    }

    private static void scene(String name, String legend, IntFunction<Camera> camera) {
        SCENES.put(name, camera);
        LEGEND.put(name, legend);
    }

    /** The camera of {@code scenes/<name>.json} at the given size and thread count. */
    private static Camera sceneFile(String name, int width, int height, int threads) {
        try {
            Path file = Path.of("scenes", name + ".json");
            SceneDocument d = SceneLoader.read(file);
            d = d.withRender(d.render().withSize(width, height).withThreads(threads));
            LoadedScene loaded = SceneLoader.build(d, file);
            return loaded.camera();
        } catch (sceneio.SceneFileException e) {
            throw new IllegalStateException("cannot load scenes/" + name + ".json: " + e.getMessage(), e);
        }
    }

    private static Row measure(Scenario s, int runs, Double lightCutoff, Path images) throws IOException {
        var threadBean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        render(s, lightCutoff); // warm-up: class loading and JIT
        Row[] rows = new Row[runs];
        Camera last = null;
        for (int i = 0; i < runs; i++) {
            // CPU time and allocation of the threads that render, read on each of them as it finishes a tile (the
            // renderer may run on the calling thread, as older builds did, or on threads of its own).
            Map<Thread, long[]> counters = new java.util.concurrent.ConcurrentHashMap<>();
            Thread caller = Thread.currentThread();
            long cpu0 = threadBean.getCurrentThreadCpuTime(), bytes0 = threadBean.getCurrentThreadAllocatedBytes();
            Camera c = render(s, lightCutoff, (done, all) -> {
                long[] v = counters.computeIfAbsent(Thread.currentThread(), t -> new long[2]);
                v[0] = threadBean.getCurrentThreadCpuTime();
                v[1] = threadBean.getCurrentThreadAllocatedBytes();
            });
            long cpu = 0, bytes = 0;
            for (Map.Entry<Thread, long[]> e : counters.entrySet()) {
                boolean isCaller = e.getKey() == caller;
                cpu += e.getValue()[0] - (isCaller ? cpu0 : 0);
                bytes += e.getValue()[1] - (isCaller ? bytes0 : 0);
            }
            RenderStatistics st = c.getLastStatistics();
            var rays = st.rays();
            long total = rays.total();
            // On one thread one thread renders everything (the camera is built before it starts).
            double perRay = s.threads() == 1 ? bytes / (double) total : Double.NaN;
            rows[i] = new Row(
                    s.key(),
                    st.wallSeconds(),
                    cpu * 1e-9,
                    rays.camera,
                    rays.shadow,
                    rays.reflection,
                    rays.refraction,
                    st.nodeVisits(),
                    st.primitiveTests(),
                    perRay,
                    "");
            last = c;
        }
        Arrays.sort(rows, (a, b) -> Double.compare(a.wallSeconds(), b.wallSeconds()));
        Row median = rows[runs / 2];
        String image = "";
        if (images != null) {
            String file = s.key().replaceAll("[^A-Za-z0-9]+", "-").replaceAll("^-|-$", "") + ".png";
            Path target = images.resolve(file).toAbsolutePath();
            ImageIO.write(last.getImage().toBufferedImage(), "png", target.toFile());
            image = target.toString();
        }
        return new Row(
                median.key(),
                median.wallSeconds(),
                median.cpuSeconds(),
                median.camera(),
                median.shadow(),
                median.reflection(),
                median.refraction(),
                median.nodeVisits(),
                median.primitiveTests(),
                median.bytesPerRay(),
                image);
    }

    private static Camera render(Scenario s, Double lightCutoff) {
        return render(s, lightCutoff, null);
    }

    private static Camera render(Scenario s, Double lightCutoff, renderer.ProgressListener listener) {
        Camera c = s.camera().apply(s.threads());
        if (listener != null) c.setProgressListener(listener);
        if (lightCutoff != null) {
            try {
                RenderSettings settings = (RenderSettings) RenderSettings.class
                        .getMethod("withLightCutoff", double.class)
                        .invoke(c.getRenderSettings(), lightCutoff);
                c.setRenderSettings(settings);
            } catch (ReflectiveOperationException e) {
                throw new IllegalArgumentException("--light-cutoff: this build has no light cut-off");
            }
        }
        c.renderImage();
        return c;
    }

    private static Map<String, Row> read(Path file) throws IOException {
        if (!Files.isRegularFile(file)) throw new IllegalArgumentException("--baseline " + file + ": no such file");
        Map<String, Row> rows = new LinkedHashMap<>();
        List<String> lines = Files.readAllLines(file);
        if (lines.isEmpty() || !lines.get(0).equals(CSV_HEADER)) {
            throw new IllegalArgumentException("--baseline " + file
                    + ": not a CSV written by this benchmark (its first line must be the header '" + CSV_HEADER + "')");
        }
        for (String line : lines.subList(1, lines.size())) {
            if (line.isBlank()) continue;
            try {
                Row r = Row.parse(line);
                rows.put(r.key(), r);
            } catch (RuntimeException e) {
                throw new IllegalArgumentException("--baseline " + file + ": unreadable row '" + line + "'");
            }
        }
        return rows;
    }

    /** "identical", how many pixels differ and by how much, or "-" when either image was not saved. */
    private static String compareImages(String oldImage, String newImage) throws IOException {
        if (oldImage.isEmpty() || newImage.isEmpty() || !Files.isRegularFile(Path.of(oldImage))) return "-";
        BufferedImage a = ImageIO.read(Path.of(oldImage).toFile()),
                b = ImageIO.read(Path.of(newImage).toFile());
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) return "different size";
        int differ = 0, most = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y), q = b.getRGB(x, y);
                int d = 0;
                for (int shift = 0; shift < 24; shift += 8) {
                    d = Math.max(d, Math.abs((p >> shift & 255) - (q >> shift & 255)));
                }
                if (d > 0) differ++;
                most = Math.max(most, d);
            }
        }
        return differ == 0
                ? "identical"
                : String.format(
                        Locale.ROOT,
                        "%,d of %,d pixels differ (%.2f%%), by at most %d",
                        differ,
                        a.getWidth() * a.getHeight(),
                        100.0 * differ / (a.getWidth() * a.getHeight()),
                        most);
    }

    private static String require(String option, String value) {
        if (value == null) throw new IllegalArgumentException(option + " needs a value");
        return value;
    }
}
