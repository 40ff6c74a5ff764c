package distributed;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.UnaryOperator;
import org.apache.spark.api.java.JavaSparkContext;
import renderer.Camera;
import renderer.ImageWriter;

/**
 * Spark's overhead on one machine (docs/SPARK.md): wall time of a plain local render with as many threads as the
 * master has cores, against the same scene as 4 and as 16 tiles on Spark, each rendered {@code runs} times,
 * interleaved so that noise from other work on the machine falls on all three alike; prints median, min and max
 * of the wall time and of this process's CPU time (driver and executor share the JVM in local mode, so the CPU
 * time holds all of Spark's work, and unlike the wall time it hardly depends on what else the machine runs).
 * Every Spark image is checked bit-identical to the local one.
 *
 * <pre>
 * mvn -q -Pspark compile exec:exec@spark -Dspark.main=distributed.SparkOverheadBenchmark \
 *     -Dspark.args="scenes/showcase.json 5"
 * </pre>
 */
public final class SparkOverheadBenchmark {
    private static final String[] NAMES = {"local", "Spark, 4 tiles", "Spark, 16 tiles"};

    private SparkOverheadBenchmark() {}

    /** CPU time of all threads of this JVM (Spark's driver and, in local mode, its executor). */
    private static long processCpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: SparkOverheadBenchmark <scene.json> [runs (default 5)]");
            System.exit(2);
        }
        Path sceneFile = Path.of(args[0]);
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 5;
        SceneBundle bundle = SceneBundle.read(sceneFile);
        long startSpark = System.nanoTime();
        try (JavaSparkContext spark = SparkContexts.open(null)) {
            double startup = (System.nanoTime() - startSpark) * 1e-9;
            int cores = spark.defaultParallelism();
            List<Tile> four = new TileGrid(2, 2).split(bundle.width(), bundle.height());
            List<Tile> sixteen = new TileGrid(4, 4).split(bundle.width(), bundle.height());
            System.out.printf(
                    Locale.ROOT,
                    "%s: %d x %d pixels; master %s (%d cores); Spark started in %.2f s; %d runs after a warm-up%n",
                    sceneFile,
                    bundle.width(),
                    bundle.height(),
                    spark.master(),
                    cores,
                    startup,
                    runs);
            ImageWriter reference = local(bundle, cores);
            SparkTileRender.render(spark, bundle, four, FaultInjection.NONE); // warm-up of the Spark path
            double[][] wall = new double[3][runs], cpu = new double[3][runs];
            List<String> mismatches = new ArrayList<>();
            for (int r = 0; r < runs; r++) {
                for (int kind = 0; kind < 3; kind++) {
                    long t = System.nanoTime(), c = processCpuNanos();
                    ImageWriter image = kind == 0
                            ? local(bundle, cores)
                            : SparkTileRender.render(spark, bundle, kind == 1 ? four : sixteen, FaultInjection.NONE);
                    wall[kind][r] = (System.nanoTime() - t) * 1e-9;
                    cpu[kind][r] = (processCpuNanos() - c) * 1e-9;
                    if (!identical(reference, image)) mismatches.add("run " + r + ", " + NAMES[kind]);
                }
                System.out.printf(
                        Locale.ROOT,
                        "run %d: wall (cpu) local %.3f (%.3f) s, 4 tiles %.3f (%.3f) s, 16 tiles %.3f (%.3f) s%n",
                        r,
                        wall[0][r],
                        cpu[0][r],
                        wall[1][r],
                        cpu[1][r],
                        wall[2][r],
                        cpu[2][r]);
            }
            for (String measure : List.of("wall", "CPU")) {
                double[][] m = measure.equals("wall") ? wall : cpu;
                double base = median(m[0]);
                System.out.println();
                System.out.println("| " + measure + " time | median s | min s | max s | vs local (median) |");
                System.out.println("|---|---|---|---|---|");
                for (int kind = 0; kind < 3; kind++) {
                    row(kind == 0 ? "local, " + cores + " threads" : NAMES[kind], m[kind], base);
                }
            }
            System.out.println(
                    mismatches.isEmpty()
                            ? "every Spark image is bit-identical to the local render"
                            : "NOT bit-identical: " + mismatches);
        }
    }

    private static ImageWriter local(SceneBundle bundle, int threads) throws Exception {
        Camera camera = bundle.load(UnaryOperator.identity()).camera();
        camera.setThreads(threads);
        return camera.renderImage().getImage();
    }

    private static boolean identical(ImageWriter a, ImageWriter b) {
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) if (!a.getPixel(x, y).equals(b.getPixel(x, y))) return false;
        }
        return true;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    private static void row(String name, double[] values, double base) {
        double median = median(values);
        System.out.printf(
                Locale.ROOT,
                "| %s | %.2f | %.2f | %.2f | %+.2f s (%+.0f%%) |%n",
                name,
                median,
                Arrays.stream(values).min().orElse(0),
                Arrays.stream(values).max().orElse(0),
                median - base,
                100 * (median - base) / base);
    }
}
