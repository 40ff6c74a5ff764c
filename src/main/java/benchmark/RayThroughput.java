package benchmark;

import geometries.Accelerator;
import geometries.HitRecord;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.concurrent.atomic.AtomicInteger;
import primitives.Ray;

/**
 * Traces a pre-generated ray array through an {@link Accelerator} (closest-hit queries over {@code (0, inf)}) on
 * a number of threads and reports the wall time. Threads take chunks of consecutive rays from a shared counter,
 * as a renderer's workers take tiles, so coherent rays stay coherent per thread and the load balances.
 */
public final class RayThroughput {
    /** Rays per work chunk: large enough that the shared counter is not contended. */
    private static final int CHUNK = 4096;

    private RayThroughput() {}

    /**
     * The result of one pass: wall time, CPU time summed over the threads (on a shared machine it excludes the
     * time other processes had the cores), hits, and BVH statistics summed over the threads.
     */
    public record Pass(double seconds, double cpuSeconds, long hits, long nodeVisits, long primitiveTests) {}

    /**
     * Traces all rays once with {@code threads} workers.
     *
     * @param accelerator the scene search to time
     * @param rays the rays to trace, each searched for its closest hit
     * @param threads the number of worker threads, at least 1
     * @return the wall and CPU time of the pass and its counts
     */
    public static Pass trace(Accelerator accelerator, Ray[] rays, int threads) {
        AtomicInteger next = new AtomicInteger();
        HitRecord[] records = new HitRecord[threads];
        long[] hits = new long[threads];
        long[] cpuNanos = new long[threads];
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        Thread[] workers = new Thread[threads];
        for (int w = 0; w < threads; w++) {
            int worker = w;
            records[w] = new HitRecord();
            workers[w] = new Thread(() -> {
                long cpuStart = cpu.getCurrentThreadCpuTime();
                hits[worker] = traceChunks(accelerator, rays, next, records[worker]);
                cpuNanos[worker] = cpu.getCurrentThreadCpuTime() - cpuStart;
            });
        }
        long start = System.nanoTime();
        for (Thread worker : workers) worker.start();
        for (Thread worker : workers) {
            try {
                worker.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("benchmark interrupted", e);
            }
        }
        double seconds = (System.nanoTime() - start) * 1e-9;
        long totalHits = 0, visits = 0, tests = 0, totalCpu = 0;
        for (int w = 0; w < threads; w++) {
            totalCpu += cpuNanos[w];
            totalHits += hits[w];
            visits += records[w].nodeVisits;
            tests += records[w].primitiveTests;
        }
        return new Pass(seconds, totalCpu * 1e-9, totalHits, visits, tests);
    }

    private static long traceChunks(Accelerator accelerator, Ray[] rays, AtomicInteger next, HitRecord hit) {
        long hits = 0;
        int start;
        while ((start = next.getAndAdd(CHUNK)) < rays.length) {
            int end = Math.min(rays.length, start + CHUNK);
            for (int i = start; i < end; i++) {
                if (accelerator.intersect(rays[i], 0, Double.POSITIVE_INFINITY, hit)) hits++;
            }
        }
        return hits;
    }

    /**
     * Closest-hit distances of each ray (NaN for a miss), for checking two searches agree.
     *
     * @param accelerator the scene search
     * @param rays the rays to trace
     * @return the distance along each ray to its closest hit, or NaN where it misses, in the order of {@code rays}
     */
    public static double[] distances(Accelerator accelerator, Ray[] rays) {
        HitRecord hit = new HitRecord();
        double[] t = new double[rays.length];
        for (int i = 0; i < rays.length; i++) {
            t[i] = accelerator.intersect(rays[i], 0, Double.POSITIVE_INFINITY, hit.reset()) ? hit.t : Double.NaN;
        }
        return t;
    }
}
