package cli;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import renderer.Camera;

/**
 * While open, a JVM shutdown (Ctrl-C, SIGTERM) cancels the camera's render and holds the shutdown until the
 * command has reported it and closed this guard (at most {@link #GRACE_MILLIS}), so the user reads "render
 * cancelled" instead of a silent exit. Temporary image files are removed by {@code AtomicFile}'s own hook.
 */
final class CancelOnShutdown implements RenderHost.CancelGuard {
    /** Longest a shutdown waits for the render threads to stop and the command to report. */
    static final long GRACE_MILLIS = 10_000;

    private final Camera camera;
    private final CountDownLatch closed = new CountDownLatch(1);
    private final Thread hook;
    private volatile boolean signalled;

    CancelOnShutdown(Camera camera) {
        this.camera = camera;
        this.hook = new Thread(this::cancelUntilClosed, "cancel-render");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** Whether a shutdown began while this guard was open: then the render's result must not be written. */
    @Override
    public boolean signalled() {
        return signalled;
    }

    private void cancelUntilClosed() {
        signalled = true;
        cancelUntil(() -> camera, closed, TimeUnit.MILLISECONDS.toNanos(GRACE_MILLIS));
    }

    /**
     * Cancels the render of {@code camera} (null: none yet) every 20 ms until {@code done} opens or {@code maxNanos}
     * have passed: again and again, because a render that starts right after a {@code cancel()} begins afresh and
     * clears it.
     *
     * @param camera the camera rendering, or giving null while there is none
     * @param done opens when the command has finished and reported
     * @param maxNanos how long to keep cancelling at most
     */
    static void cancelUntil(Supplier<Camera> camera, CountDownLatch done, long maxNanos) {
        long start = System.nanoTime();
        try {
            do {
                Camera c = camera.get();
                if (c != null) c.cancel();
            } while (!done.await(20, TimeUnit.MILLISECONDS) && System.nanoTime() - start < maxNanos);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Lets a shutdown proceed, and removes the hook when no shutdown is under way. */
    @Override
    public void close() {
        closed.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is exiting: the hook has run or is running
        }
    }
}
