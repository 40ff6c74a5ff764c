package cli;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
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
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(GRACE_MILLIS);
        try {
            // Cancelled again and again: a render that starts right after a cancel() begins afresh and clears it.
            do {
                camera.cancel();
            } while (!closed.await(20, TimeUnit.MILLISECONDS) && System.nanoTime() < deadline);
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
