package benchmark;

import app.StreetOptions;
import app.StreetScene;
import geometries.Accelerator;
import geometries.BoundingBox;
import geometries.Geometries;
import geometries.Intersectable;
import geometries.Meshes;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The BVH benchmark: for each workload, builds the scene's {@link Accelerator}, traces coherent (pinhole) and
 * incoherent (random) closest-hit rays with the BVH on 1..N threads and by brute force on an evenly spread sample,
 * and prints a Markdown table. Every timing is the median of several passes after a warm-up pass.
 *
 * <p>Run: {@code mvn -q -Pbenchmark compile exec:exec}; options go in {@code -Dbenchmark.args="..."}:
 * {@code runs=5} (timed passes per figure), {@code threads=1,2}, {@code only=heightfield-100k,spheres-polygons}.
 */
public final class BvhBenchmark {
    /** Pinhole resolution of the coherent rays. */
    public static final int IMAGE_SIZE = 1024;
    /** Vertical field of view of the coherent rays, degrees. */
    public static final double FOV_DEGREES = 45;
    /** Incoherent rays per workload. */
    public static final int INCOHERENT_RAYS = 1 << 20;
    /** Seed of the incoherent rays and of the spheres-polygons scene. */
    public static final long SEED = 20240613L;
    /** Primitive tests a brute-force pass may spend: sets the size of its ray sample. */
    private static final double BRUTE_FORCE_BUDGET = 2e7;

    private static final Vector UP_Z = new Vector(0, 0, 1);
    /** Most builds before the timed ones (the first one included). */
    private static final int WARM_UP_BUILDS = 10;
    /**
     * Fewest builds before the timed ones (the first one included). A build runs some loops once per build (the root's
     * summary, the collapse's sweep, the layout's positions), which the JIT compiles only after a build or two: a
     * fresh JVM built the 1M heightfield in 1.09, 0.40, 0.36, 0.21, 0.25, 0.27, 0.23, 0.20 ... s (27 Nov), so three
     * builds after the first still ran code the JIT had not finished.
     */
    private static final int MIN_WARM_UP_BUILDS = 5;

    /** The workloads; adding one is adding a line. */
    public static final List<Workload> WORKLOADS = List.of(
            new Workload(
                    "heightfield-100k",
                    () -> Meshes.heightfield(224),
                    new Point(0, -0.5, 1.8),
                    new Point(0, 0.05, 0),
                    UP_Z),
            new Workload(
                    "heightfield-1M",
                    () -> Meshes.heightfield(708),
                    new Point(0, -0.5, 1.8),
                    new Point(0, 0.05, 0),
                    UP_Z),
            new Workload("icosphere-82k", () -> Meshes.icosphere(6), new Point(0, -3, 0), Point.ZERO, UP_Z),
            new Workload("icosphere-1.3M", () -> Meshes.icosphere(8), new Point(0, -3, 0), Point.ZERO, UP_Z),
            new Workload(
                    "spheres-polygons",
                    () -> BenchmarkScenes.spheresAndPolygons(200, 200, SEED),
                    new Point(0, -45, 15),
                    new Point(0, 0, 3),
                    UP_Z),
            new Workload(
                    "street",
                    () -> new StreetScene(StreetOptions.HARD).scene().geometries,
                    StreetScene.CAMERA_LOCATION,
                    StreetScene.CAMERA_TARGET,
                    UP_Z,
                    boundedPart(new StreetScene(StreetOptions.HARD).scene().geometries)));

    /** The union of the bounded members' boxes: where incoherent rays start in a scene with a ground plane. */
    static BoundingBox boundedPart(Geometries scene) {
        BoundingBox box = null;
        for (Intersectable member : scene.getMembers()) {
            BoundingBox b = member.getBoundingBox();
            if (b != null) box = box == null ? b : box.union(b);
        }
        return box;
    }

    private final int runs;
    private final int[] threadCounts;
    private final List<String> only;

    private BvhBenchmark(int runs, int[] threadCounts, List<String> only) {
        this.runs = runs;
        this.threadCounts = threadCounts;
        this.only = only;
    }

    /**
     * Runs the benchmark and prints the table.
     *
     * @param args options as {@code key=value}: {@code runs=N} (1 to 1000), {@code threads=1,2,...} (each 1 to 256),
     *     {@code only=name,...}
     * @throws IllegalArgumentException if an option is unknown or out of range
     */
    public static void main(String[] args) {
        int runs = 5;
        int cores = Runtime.getRuntime().availableProcessors();
        int[] threads = new int[cores];
        for (int i = 0; i < cores; i++) threads[i] = i + 1;
        List<String> only = List.of();
        for (String arg : args) {
            String[] kv = arg.split("=", 2);
            if (kv.length != 2) throw new IllegalArgumentException("expected key=value, but got " + arg);
            switch (kv[0]) {
                case "runs" -> runs = Integer.parseInt(kv[1]);
                case "threads" ->
                    threads = Arrays.stream(kv[1].split(","))
                            .mapToInt(Integer::parseInt)
                            .toArray();
                case "only" -> only = List.of(kv[1].split(","));
                default -> throw new IllegalArgumentException("unknown option " + kv[0] + " (runs, threads, only)");
            }
        }
        if (runs < 1 || runs > 1000) throw new IllegalArgumentException("runs must be in [1, 1000], but was " + runs);
        for (int t : threads) {
            if (t < 1 || t > 256) throw new IllegalArgumentException("threads must be in [1, 256], but was " + t);
        }
        new BvhBenchmark(runs, threads, only).run();
    }

    private void run() {
        System.out.printf(
                Locale.ROOT,
                "BVH benchmark: %d timed passes per figure (median), threads %s, %d cores, Java %s, JVM flags %s%n%n",
                runs,
                Arrays.toString(threadCounts),
                Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"),
                ManagementFactory.getRuntimeMXBean().getInputArguments());
        List<String> rows = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        for (Workload workload : WORKLOADS) {
            if (!only.isEmpty() && !only.contains(workload.name())) continue;
            measure(workload, rows, notes);
        }
        System.out.println();
        System.out.println(header());
        rows.forEach(System.out::println);
        System.out.println();
        notes.forEach(System.out::println);
    }

    private String header() {
        StringBuilder h = new StringBuilder("| workload | rays | primitives | build s, wall (CPU) |");
        StringBuilder line = new StringBuilder("|---|---|--:|--:|");
        for (int t : threadCounts) {
            h.append(" ").append(t).append("T M rays/s/thread, wall (CPU) |");
            line.append("--:|");
        }
        int last = threadCounts[threadCounts.length - 1];
        h.append(" scaling ").append(last).append("T/").append(threadCounts[0]).append("T, wall (CPU) |");
        h.append(" brute M rays/CPU-s | BVH/brute (1T, CPU) | nodes/ray | tests/ray | BVH B/prim | hit % |");
        line.append("--:|--:|--:|--:|--:|--:|--:|");
        return h + "\n" + line;
    }

    /** The timed builds in the order they ran, so a median can be read beside its spread. */
    private static String seconds(double[] seconds) {
        StringBuilder s = new StringBuilder();
        for (double t : seconds) s.append(s.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.3f", t));
        return s.toString();
    }

    private void measure(Workload workload, List<String> rows, List<String> notes) {
        System.out.println("== " + workload.name());
        Intersectable scene = workload.scene().get();

        double[] buildSeconds = new double[Math.max(3, runs)];
        double[] buildCpuSeconds = new double[buildSeconds.length];
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        // The first build runs while the JIT compiles the builder: timed apart. Then untimed builds, at least
        // MIN_WARM_UP_BUILDS in all and for at least a second (at most WARM_UP_BUILDS), so that the timed builds run
        // compiled code.
        long firstStart = System.nanoTime();
        Accelerator bvh = Accelerator.build(scene, true);
        double firstBuild = (System.nanoTime() - firstStart) * 1e-9;
        int untimed = 0;
        while (1 + untimed < MIN_WARM_UP_BUILDS
                || (1 + untimed < WARM_UP_BUILDS && System.nanoTime() - firstStart < 1_000_000_000L)) {
            bvh = Accelerator.build(scene, true);
            untimed++;
        }
        for (int i = 0; i < buildSeconds.length; i++) {
            bvh = null; // let the previous build be collected before timing the next
            long cpuStart = cpu.getCurrentThreadCpuTime();
            long start = System.nanoTime();
            bvh = Accelerator.build(scene, true);
            buildSeconds[i] = (System.nanoTime() - start) * 1e-9;
            buildCpuSeconds[i] = (cpu.getCurrentThreadCpuTime() - cpuStart) * 1e-9;
        }
        double build = median(buildSeconds);
        double buildCpu = median(buildCpuSeconds);
        Accelerator brute = Accelerator.build(scene, false);
        int primitives = bvh.boundedPrimitiveCount() + bvh.unboundedPrimitiveCount();
        double bytesPerPrimitive = (double) bvh.getBvh().bytes() / primitives;
        notes.add(String.format(
                Locale.ROOT,
                "- %s: build %.3f s wall, %.3f s CPU (medians of %d: %s s, after a first build of %.3f s and %d untimed ones); last build: %s; BVH %d nodes, %d leaves, depth %d, %.1f B/prim"
                        + " (all flat arrays %.1f B/prim)",
                workload.name(),
                build,
                buildCpu,
                buildSeconds.length,
                seconds(buildSeconds),
                firstBuild,
                untimed,
                bvh.buildBreakdown(),
                bvh.getBvh().nodeCount(),
                bvh.getBvh().leafCount(),
                bvh.getBvh().depth(),
                bytesPerPrimitive,
                (double) bvh.bytes() / primitives));

        BoundingBox box = workload.rayBox() != null ? workload.rayBox() : bvh.getBoundingBox();
        Ray[] coherent =
                RaySets.pinhole(workload.eye(), workload.target(), workload.up(), FOV_DEGREES, IMAGE_SIZE, IMAGE_SIZE);
        rows.add(
                row(workload, "coherent", coherent, bvh, brute, primitives, build, buildCpu, bytesPerPrimitive, notes));
        coherent = null;
        Ray[] incoherent = RaySets.incoherent(box, INCOHERENT_RAYS, SEED);
        rows.add(row(
                workload, "incoherent", incoherent, bvh, brute, primitives, build, buildCpu, bytesPerPrimitive, notes));
    }

    private String row(
            Workload workload,
            String kind,
            Ray[] rays,
            Accelerator bvh,
            Accelerator brute,
            int primitives,
            double build,
            double buildCpu,
            double bytesPerPrimitive,
            List<String> notes) {
        StringBuilder row = new StringBuilder();
        row.append(String.format(
                Locale.ROOT, "| %s | %s | %,d | %.3f (%.3f) |", workload.name(), kind, primitives, build, buildCpu));
        double[] perThread = new double[threadCounts.length];
        double[] perCpuSecond = new double[threadCounts.length];
        RayThroughput.Pass stats = null;
        for (int c = 0; c < threadCounts.length; c++) {
            int threads = threadCounts[c];
            RayThroughput.trace(bvh, rays, threads); // warm-up
            double[] seconds = new double[runs];
            double[] cpuSeconds = new double[runs];
            for (int r = 0; r < runs; r++) {
                RayThroughput.Pass pass = RayThroughput.trace(bvh, rays, threads);
                seconds[r] = pass.seconds();
                cpuSeconds[r] = pass.cpuSeconds();
                if (threads == 1 || stats == null) stats = pass;
            }
            perThread[c] = rays.length / median(seconds) / threads * 1e-6;
            perCpuSecond[c] = rays.length / median(cpuSeconds) * 1e-6;
            row.append(String.format(Locale.ROOT, " %.2f (%.2f) |", perThread[c], perCpuSecond[c]));
            System.out.printf(
                    Locale.ROOT,
                    "   %-10s %dT: %.2f M rays/s/thread, %.2f M rays per CPU second (wall s %s)%n",
                    kind,
                    threads,
                    perThread[c],
                    perCpuSecond[c],
                    Arrays.toString(Arrays.stream(seconds)
                            .mapToObj(s -> String.format(Locale.ROOT, "%.3f", s))
                            .toArray()));
        }
        int last = threadCounts.length - 1;
        double scaling = perThread[last] * threadCounts[last] / (perThread[0] * threadCounts[0]);
        // What the threads would give with the cores to themselves: CPU-time throughput times the thread ratio.
        double cpuScaling = perCpuSecond[last] * threadCounts[last] / (perCpuSecond[0] * threadCounts[0]);

        // Brute force on an evenly spread sample sized to the budget; it must agree with the BVH exactly.
        int stride = (int) Math.max(1, Math.ceil(rays.length * (double) primitives / BRUTE_FORCE_BUDGET));
        Ray[] sample = RaySets.sample(rays, stride);
        RayThroughput.trace(brute, sample, 1); // warm-up
        double[] seconds = new double[runs];
        for (int r = 0; r < runs; r++) {
            seconds[r] = RayThroughput.trace(brute, sample, 1).cpuSeconds();
        }
        double bruteRate = sample.length / median(seconds) * 1e-6; // per CPU second, like the BVH figure it divides
        int disagreements = disagreements(bvh, brute, sample);
        if (disagreements > 0) {
            notes.add("- WARNING " + workload.name() + " " + kind + ": BVH and brute force disagree on " + disagreements
                    + " of " + sample.length + " sampled rays");
        }
        row.append(String.format(
                Locale.ROOT,
                " %.2fx (%.2fx) | %.3g | %,.0fx | %.1f | %.1f | %.0f | %.1f |",
                scaling,
                cpuScaling,
                bruteRate,
                perCpuSecond[0] / bruteRate,
                (double) stats.nodeVisits() / rays.length,
                (double) stats.primitiveTests() / rays.length,
                bytesPerPrimitive,
                100.0 * stats.hits() / rays.length));
        System.out.printf(
                Locale.ROOT,
                "   %-10s brute force on %d sampled rays: %.3g M rays per CPU second%n",
                kind,
                sample.length,
                bruteRate);
        return row.toString();
    }

    private static int disagreements(Accelerator a, Accelerator b, Ray[] rays) {
        double[] ta = RayThroughput.distances(a, rays);
        double[] tb = RayThroughput.distances(b, rays);
        int count = 0;
        for (int i = 0; i < rays.length; i++) {
            if (Double.doubleToLongBits(ta[i]) != Double.doubleToLongBits(tb[i])) count++;
        }
        return count;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
}
