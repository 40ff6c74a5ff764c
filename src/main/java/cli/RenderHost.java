package cli;

import java.io.PrintStream;
import renderer.Camera;

/**
 * Where a {@code render} command runs: in its own JVM ({@link #LOCAL}), or in the render daemon for a client in
 * another process ({@link RenderDaemon}). The command asks its host where a progress bar is drawn, whether a person
 * watches it, and what cancels the render.
 */
interface RenderHost {
    /** The command's own JVM: the bar on this process' stderr, cancelled by Ctrl-C or SIGTERM. */
    RenderHost LOCAL = new RenderHost() {
        @Override
        public PrintStream terminal() {
            return System.err;
        }

        @Override
        public boolean interactive() {
            return Terminal.interactive();
        }

        @Override
        public CancelGuard guard(Camera camera) {
            return new CancelOnShutdown(camera);
        }
    };

    /** The stream a progress bar redraws in place. */
    PrintStream terminal();

    /** Whether a person watches {@link #terminal()}: then {@code --progress auto} draws a bar. */
    boolean interactive();

    /**
     * A guard that cancels {@code camera}'s render when the user asks, open until the command has reported.
     *
     * @param camera the camera about to render
     * @return the guard; the command closes it when the render has ended and been reported
     */
    CancelGuard guard(Camera camera);

    /** Cancels a render on the user's request while open. */
    interface CancelGuard extends AutoCloseable {
        /** Whether the user asked to cancel while this guard was open: then the result must not be written. */
        boolean signalled();

        @Override
        void close();
    }
}
