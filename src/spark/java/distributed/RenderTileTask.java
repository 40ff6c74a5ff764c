package distributed;

import java.util.function.UnaryOperator;
import org.apache.spark.api.java.function.Function;
import org.apache.spark.broadcast.Broadcast;
import renderer.Camera;
import renderer.ImageRegion;
import sceneio.SceneFileException;

/**
 * The work of one Spark task of a tiled render (on an executor): load the broadcast scene and render one tile with
 * {@link Camera#renderRegion}. Its pixels depend only on the scene and the tile, never on the executor, the
 * attempt or the other tasks, so a retried or speculative copy returns the same bits.
 */
final class RenderTileTask implements Function<Tile, ImageRegion> {
    private static final long serialVersionUID = 1L;

    private final Broadcast<SceneBundle> scene;
    private final FaultInjection faults;

    RenderTileTask(Broadcast<SceneBundle> scene, FaultInjection faults) {
        this.scene = scene;
        this.faults = faults;
    }

    @Override
    public ImageRegion call(Tile tile) throws SceneFileException {
        Camera camera = scene.value().load(UnaryOperator.identity()).camera();
        camera.setThreads(TaskThreads.get());
        ImageRegion region = camera.renderRegion(tile.x0(), tile.y0(), tile.width(), tile.height());
        faults.afterRendering("tile", tile.index());
        return region;
    }
}
