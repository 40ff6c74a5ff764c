package cli;

import java.io.PrintStream;
import java.io.PrintWriter;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;
import renderer.ProgressListener;

/**
 * Shows a render's tile progress on stderr: a progress bar (me.tongfei progressbar) in a terminal, or plain ASCII
 * lines at every 10% otherwise. Called from the render threads, so every method is synchronized; the bar is
 * created on the first tile because only then is the tile count known.
 */
abstract class RenderProgress implements ProgressListener, AutoCloseable {
    /**
     * A listener for {@code mode}; AUTO picks the bar when a person watches the terminal ({@link Terminal}).
     *
     * @param mode the mode asked for
     * @param stderr where a bar is redrawn
     * @param interactive whether a person watches {@code stderr}
     * @param lines where progress lines are printed
     */
    static RenderProgress create(ProgressMode mode, PrintStream stderr, boolean interactive, PrintWriter lines) {
        ProgressMode m = mode;
        if (m == ProgressMode.AUTO) m = interactive ? ProgressMode.BAR : ProgressMode.LINES;
        return switch (m) {
            case BAR -> new Bar(stderr);
            case LINES -> new Lines(lines);
            default -> new None();
        };
    }

    @Override
    public abstract void close();

    /** Redraws an ASCII bar in place. */
    private static final class Bar extends RenderProgress {
        private final PrintStream stderr;
        private ProgressBar bar;

        Bar(PrintStream stderr) {
            this.stderr = stderr;
        }

        @Override
        public synchronized void tileFinished(int done, int total) {
            if (bar == null) {
                bar = new ProgressBarBuilder()
                        .setTaskName("render")
                        .setInitialMax(total)
                        .setUnit(" tiles", 1)
                        .setStyle(ProgressBarStyle.ASCII)
                        .setUpdateIntervalMillis(200)
                        .setConsumer(new ConsoleProgressBarConsumer(stderr))
                        .build();
            }
            bar.stepTo(done);
        }

        @Override
        public synchronized void close() {
            if (bar != null) bar.close();
        }
    }

    /** "render: 30% (48/160 tiles)" at every tenth. */
    static final class Lines extends RenderProgress {
        private final PrintWriter out;
        private int lastTenth = 0;

        Lines(PrintWriter out) {
            this.out = out;
        }

        @Override
        public synchronized void tileFinished(int done, int total) {
            int tenth = (int) (10L * done / total);
            if (tenth > lastTenth) {
                lastTenth = tenth;
                out.println("render: " + tenth * 10 + "% (" + done + "/" + total + " tiles)");
                out.flush();
            }
        }

        @Override
        public void close() {}
    }

    /** Shows nothing. */
    private static final class None extends RenderProgress {
        @Override
        public void tileFinished(int done, int total) {}

        @Override
        public void close() {}
    }
}
