package geometries;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.TimeUnit;
import java.util.function.IntConsumer;
import java.util.function.Supplier;
import java.util.stream.IntStream;

/**
 * The fork/join pool every parallel step of a build runs in (the tree's top, the primitives' boxes, their layout, the
 * collapse to wide nodes), one worker per core: the common pool leaves a core to a caller that waits. Its idle workers
 * end after {@link #IDLE_SECONDS} s, where the JDK's pools keep them 60 s: a host that waits for a program's threads
 * when it ends ({@code mvn exec:java} interrupts them and waits 15 s, and fork/join workers ignore interrupts) waited
 * that long after every render, README's main job included.
 */
final class BuildPool {
    static final int IDLE_SECONDS = 1;

    private static volatile ForkJoinPool pool;

    private BuildPool() {}

    /**
     * Runs {@code work} in the pool and returns its result; parallel streams inside it run in the pool too.
     *
     * @param work the work
     * @param <T> its result's type
     * @return its result
     */
    static <T> T invoke(Supplier<T> work) {
        return pool().invoke(ForkJoinTask.adapt(work::get));
    }

    /**
     * Calls {@code action} for every index in [0, n), on all cores where {@code parallel}, else in order here.
     *
     * @param n the number of indices
     * @param parallel whether to spread the calls over the pool's workers
     * @param action what to do for an index (independent of the others when parallel)
     */
    static void forEach(int n, boolean parallel, IntConsumer action) {
        if (!parallel) {
            for (int i = 0; i < n; i++) action.accept(i);
            return;
        }
        invoke(() -> {
            IntStream.range(0, n).parallel().forEach(action);
            return null;
        });
    }

    /** What {@link #forEachChunk} does for one chunk: indices {@code [from, to)}, the {@code chunk}-th. */
    @FunctionalInterface
    interface ChunkAction {
        void accept(int chunk, int from, int to);
    }

    /** The number of chunks of {@code size} indices that {@link #forEachChunk} makes of [0, n). */
    static int chunks(int n, int size) {
        return (n + size - 1) / size;
    }

    /**
     * Calls {@code action} for consecutive chunks of {@code size} indices covering [0, n) (the last one shorter), on
     * all cores where {@code parallel} and there is more than one chunk: one call per chunk, so a cheap loop over
     * its indices pays no call per index.
     *
     * @param n the number of indices
     * @param size indices per chunk, positive
     * @param parallel whether to spread the chunks over the pool's workers
     * @param action what to do for a chunk (independent of the others when parallel)
     */
    static void forEachChunk(int n, int size, boolean parallel, ChunkAction action) {
        int chunks = chunks(n, size);
        forEach(chunks, parallel && chunks > 1, c -> action.accept(c, c * size, Math.min(n, (c + 1) * size)));
    }

    /** Whether the calling thread is one of the pool's workers. */
    static boolean isWorker() {
        return Thread.currentThread() instanceof ForkJoinWorkerThread worker && worker.getPool() == pool;
    }

    /** The pool's live worker threads (0 before the first parallel step and once idle workers have ended). */
    static int threads() {
        ForkJoinPool p = pool;
        return p == null ? 0 : p.getPoolSize();
    }

    private static synchronized ForkJoinPool pool() {
        if (pool == null) {
            // The JDK's defaults but the keep-alive (up to 32,767 threads: a worker that waits on a join may be
            // replaced by a spare; a pool capped at the core count refuses it).
            pool = new ForkJoinPool(
                    Runtime.getRuntime().availableProcessors(),
                    ForkJoinPool.defaultForkJoinWorkerThreadFactory,
                    null,
                    false,
                    0,
                    0x7fff,
                    1,
                    null,
                    IDLE_SECONDS,
                    TimeUnit.SECONDS);
        }
        return pool;
    }
}
