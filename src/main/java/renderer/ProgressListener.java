package renderer;

/** Told about render progress, once per finished tile, from the render threads (so it must be thread-safe). */
@FunctionalInterface
public interface ProgressListener {
    /** {@code done} of {@code total} tiles are finished. */
    void tileFinished(int done, int total);
}
