package renderer;

import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

/**
 * The render threads: a pass over a rectangle of the image in square tiles, taken from a shared queue by one thread
 * per {@link TraceContext}, each thread started with a stack of its own size. A render is cancelled by the
 * {@code cancelled} flag or by interrupting the calling thread; a failure on any thread stops the others and is
 * rethrown to the caller.
 */
final class TileRunner {
    /** Side of the square tiles the render threads take from the queue, in pixels. */
    static final int TILE = 16;

    private final ProgressListener progress;
    private final BooleanSupplier cancelled;

    /**
     * @param progress told about every finished tile, or null
     * @param cancelled whether the render was cancelled (read at every row)
     */
    TileRunner(ProgressListener progress, BooleanSupplier cancelled) {
        this.progress = progress;
        this.cancelled = cancelled;
    }

    /** Work on one pixel of a pass, on a render thread. */
    @FunctionalInterface
    interface PixelWork {
        void run(int x, int y, TraceContext ctx);
    }

    /**
     * One pass over a rectangle in 16 x 16 tiles on the render threads (one per context); a cancelled or interrupted
     * render throws {@link CancellationException}, a failure on a render thread is rethrown here.
     */
    void run(int x0, int y0, int width, int height, List<TraceContext> contexts, PixelWork work) {
        Thread caller = Thread.currentThread();
        // Set once the caller was interrupted or cancel() called: every render thread stops at its next row.
        AtomicBoolean stop = new AtomicBoolean();
        int xEnd = x0 + width, yEnd = y0 + height;
        int tilesX = (width + TILE - 1) / TILE, tilesY = (height + TILE - 1) / TILE, total = tilesX * tilesY;
        AtomicInteger next = new AtomicInteger();
        AtomicInteger done = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Runnable[] jobs = new Runnable[contexts.size()];
        for (int w = 0; w < jobs.length; w++) {
            TraceContext ctx = contexts.get(w);
            jobs[w] = () -> {
                try {
                    for (int t = next.getAndIncrement();
                            t < total && failure.get() == null;
                            t = next.getAndIncrement()) {
                        int tx = x0 + (t % tilesX) * TILE, ty = y0 + (t / tilesX) * TILE;
                        for (int y = ty; y < Math.min(ty + TILE, yEnd); y++) {
                            if (stop.get() || cancelled.getAsBoolean() || caller.isInterrupted()) {
                                stop.set(true);
                                throw new CancellationException("render cancelled after " + done.get() + " of " + total
                                        + " tiles; no image was produced");
                            }
                            for (int x = tx; x < Math.min(tx + TILE, xEnd); x++) work.run(x, y, ctx);
                        }
                        int finished = done.incrementAndGet();
                        if (progress != null) progress.tileFinished(finished, total);
                    }
                } catch (Throwable e) {
                    failure.compareAndSet(null, e);
                }
            };
        }
        runAll(jobs, () -> stop.set(true));
        Throwable error = failure.get();
        if (error instanceof RuntimeException re) throw re;
        if (error instanceof Error err) throw err;
        if (error != null) throw new IllegalStateException("render failed: " + error, error);
    }

    /**
     * Stack of each render thread: recursion to {@link RenderSettings#MAX_LEVEL} between two perfect mirrors needs
     * about 1 MB interpreted; 8 MB leaves room, whatever stack the calling thread has (only reserved, not used).
     */
    private static final long RENDER_STACK_BYTES = 8L << 20;

    /**
     * Runs the jobs on threads of their own, with a known stack, and waits for them; {@code onInterrupt} runs if
     * the caller is interrupted while it waits (waiting clears the interrupt status, so the jobs would not see
     * it), and the status is restored at the end.
     */
    private static void runAll(Runnable[] jobs, Runnable onInterrupt) {
        Thread[] started = new Thread[jobs.length];
        for (int i = 0; i < started.length; i++) {
            started[i] = new Thread(null, jobs[i], "render-" + i, RENDER_STACK_BYTES);
            started[i].start();
        }
        for (Thread t : started) {
            boolean interrupted = false;
            while (true) {
                try {
                    t.join();
                    break;
                } catch (InterruptedException e) {
                    interrupted = true;
                    onInterrupt.run();
                }
            }
            if (interrupted) Thread.currentThread().interrupt();
        }
    }
}
