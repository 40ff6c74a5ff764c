package geometries;

import benchmark.BvhBenchmark;
import benchmark.RaySets;
import benchmark.RayThroughput;
import benchmark.Workload;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
import primitives.Ray;

/**
 * Exports what the closest-hit kernel reads, for its C twin ({@code benchmarks/kernel-twin/twin.c}), and times the
 * library on the same rays. For one of {@link BvhBenchmark}'s mesh workloads it writes the wide nodes, the flat
 * triangles and their records, the benchmark's coherent and incoherent rays (origin and unit direction, six doubles
 * each), and the distance the library finds along each ray (-1 for a miss); the twin traces the same rays through the
 * same arrays with the same operations and checks every distance bit for bit. Then it traces both sets in this JVM,
 * one thread, and prints the median of the passes in M rays per CPU-second, as the benchmark does. The two figures
 * are the same work compiled by HotSpot and by gcc (docs/BENCHMARKS.md, "27 Nov, 14:00-14:40 UTC: the kernel's C
 * twin").
 *
 * <p>Usage: {@code KernelTwinExport DIR WORKLOAD PASSES [time-only]}, run by {@code benchmarks/kernel-twin/run.sh}.
 * It lives in the test sources to reach the package-private arrays without shipping in the library.
 */
public final class KernelTwinExport {
    /** Little-endian ints at the start of the header file: the layout the twin checks against its own. */
    static final int[] LAYOUT = {
        BVH.WIDTH,
        BVH.NODE_STRIDE,
        BVH.FIRST_NODE,
        BVH.MIN_X,
        BVH.MAX_X,
        BVH.LINK,
        BVH.COUNT,
        CompiledPrimitives.INFO,
        CompiledPrimitives.INDEX,
        CompiledPrimitives.EDGES,
        CompiledPrimitives.FILLED
    };

    private KernelTwinExport() {}

    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: KernelTwinExport DIR WORKLOAD PASSES [time-only]");
            System.exit(2);
        }
        Path dir = Path.of(args[0]);
        Workload workload = BvhBenchmark.WORKLOADS.stream()
                .filter(w -> w.name().equals(args[1]))
                .findFirst()
                .orElse(null);
        if (workload == null) {
            System.err.println("no workload named " + args[1] + "; the benchmark's are: "
                    + BvhBenchmark.WORKLOADS.stream().map(Workload::name).toList());
            System.exit(2);
        }
        int passes = Integer.parseInt(args[2]);
        Accelerator accelerator = Accelerator.build(workload.scene().get(), true);
        if (!onlyTriangles(accelerator.compiledPrimitives())) {
            System.err.println(
                    workload.name() + " holds other shapes than triangles or unbounded geometry; the twin "
                            + "traces a tree of triangles only: heightfield-100k, heightfield-1M, icosphere-82k, icosphere-1.3M");
            System.exit(2);
        }
        Ray[][] sets = {
            RaySets.pinhole(
                    workload.eye(),
                    workload.target(),
                    workload.up(),
                    BvhBenchmark.FOV_DEGREES,
                    BvhBenchmark.IMAGE_SIZE,
                    BvhBenchmark.IMAGE_SIZE),
            RaySets.incoherent(accelerator.getBoundingBox(), BvhBenchmark.INCOHERENT_RAYS, BvhBenchmark.SEED)
        };
        String[] names = {"coherent", "incoherent"};
        if (!(args.length > 3 && args[3].equals("time-only"))) {
            Files.createDirectories(dir);
            export(accelerator, sets, names, dir);
        }
        for (int s = 0; s < sets.length && passes > 0; s++) {
            System.out.printf(
                    "java %s %s: %.2f M rays/CPU-s%n", workload.name(), names[s], speed(accelerator, sets[s], passes));
        }
    }

    /** Whether every primitive is a triangle in the tree, the only kind the twin traces. */
    static boolean onlyTriangles(CompiledPrimitives primitives) {
        if (primitives.unbounded.length > 0) return false;
        for (int k = 0; k < primitives.boundedCount; k++) {
            if (primitives.info[CompiledPrimitives.INFO * k + CompiledPrimitives.EDGES] == CompiledPrimitives.OBJECT) {
                return false;
            }
        }
        return true;
    }

    /** Writes the header, the kernel's arrays, each ray set and its distances into {@code dir}. */
    static void export(Accelerator accelerator, Ray[][] sets, String[] names, Path dir) throws IOException {
        BVH bvh = accelerator.getBvh();
        CompiledPrimitives primitives = accelerator.compiledPrimitives();
        ByteBuffer header = buffer(4 * (LAYOUT.length + 7));
        for (int value : LAYOUT) header.putInt(value);
        header.putInt(bvh.rootLink).putInt(bvh.rootCount);
        header.putInt(bvh.nodes.length).putInt(primitives.triangles.length).putInt(primitives.info.length);
        header.putInt(sets[0].length).putInt(sets[1].length);
        write(dir.resolve("header"), header);
        ByteBuffer nodes = buffer(4 * bvh.nodes.length);
        for (float f : bvh.nodes) nodes.putFloat(f);
        write(dir.resolve("nodes"), nodes);
        ByteBuffer triangles = buffer(8 * primitives.triangles.length);
        for (double d : primitives.triangles) triangles.putDouble(d);
        write(dir.resolve("triangles"), triangles);
        ByteBuffer info = buffer(4 * primitives.info.length);
        for (int i : primitives.info) info.putInt(i);
        write(dir.resolve("info"), info);
        for (int s = 0; s < sets.length; s++) {
            ByteBuffer rays = buffer(48 * sets[s].length), distances = buffer(8 * sets[s].length);
            for (Ray r : sets[s]) {
                rays.putDouble(r.ox()).putDouble(r.oy()).putDouble(r.oz());
                rays.putDouble(r.dx()).putDouble(r.dy()).putDouble(r.dz());
            }
            // The twin marks a miss -1 (the benchmark's check, NaN).
            for (double t : RayThroughput.distances(accelerator, sets[s]))
                distances.putDouble(Double.isNaN(t) ? -1 : t);
            write(dir.resolve(names[s]), rays);
            write(dir.resolve(names[s] + ".t"), distances);
        }
    }

    /**
     * M rays per CPU-second on one thread, as the benchmark times them ({@link RayThroughput#trace}): the median of
     * {@code passes} passes after two untimed ones.
     */
    static double speed(Accelerator accelerator, Ray[] rays, int passes) {
        double[] speeds = new double[passes];
        for (int p = -2; p < passes; p++) {
            double cpuSeconds = RayThroughput.trace(accelerator, rays, 1).cpuSeconds();
            if (p >= 0) speeds[p] = rays.length / cpuSeconds / 1e6;
        }
        Arrays.sort(speeds);
        return speeds[passes / 2];
    }

    private static ByteBuffer buffer(int bytes) {
        return ByteBuffer.allocate(bytes).order(ByteOrder.LITTLE_ENDIAN);
    }

    private static void write(Path file, ByteBuffer data) throws IOException {
        data.flip();
        try (FileChannel channel = FileChannel.open(
                file, StandardOpenOption.CREATE, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
            while (data.hasRemaining()) channel.write(data);
        }
    }
}
