package renderer;

/** Told about render progress, once per finished tile, from the render threads (so it must be thread-safe). */
@FunctionalInterface
public interface ProgressListener {
    /**
     * {@code done} of {@code total} tiles are finished.
     *
     * @param done the number of finished tiles, 1 to {@code total}
     * @param total the number of tiles of the render
     */
    void tileFinished(int done, int total);
}
