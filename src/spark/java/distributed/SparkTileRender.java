package distributed;

import cli.RenderOverrides;
import java.nio.file.Path;
import java.util.List;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import renderer.Camera;
import renderer.ImageRegion;
import renderer.ImageWriter;
import sceneio.SceneFileException;

/**
 * A still image rendered on Spark: the image is split into tiles, each tile is one task that renders its
 * rectangle on an executor ({@link RenderTileTask}), and the driver stitches the returned pixels into one image.
 * The result is bit-identical to {@link Camera#renderImage()} of the same scene file on one machine.
 *
 * <p>Data moved: the scene (text and OBJ files) once per executor as a broadcast, a few numbers per task, and the
 * tile's linear pixels back (24 bytes per pixel, so the stitched image is exact, not rounded to 8 bits).
 */
public final class SparkTileRender {
    private SparkTileRender() {}

    /**
     * Renders the scene file, with the command-line overrides, split by {@code grid}. The scene is loaded on the driver first, so a bad file fails
     * with the CLI's message before any task is launched.
     *
     * @return the stitched image
     */
    public static ImageWriter render(
            JavaSparkContext spark, Path sceneFile, RenderOverrides overrides, TileGrid grid, FaultInjection faults)
            throws SceneFileException {
        SceneBundle bundle = SceneBundle.read(sceneFile, overrides);
        return render(spark, bundle, grid.split(bundle.width(), bundle.height()), faults);
    }

    /** Renders the tiles (one task each) of the image of a scene bundle read on the driver. */
    static ImageWriter render(JavaSparkContext spark, SceneBundle bundle, List<Tile> tiles, FaultInjection faults) {
        Broadcast<SceneBundle> scene = spark.broadcast(bundle);
        try {
            // One tile per partition, so one task per tile: a failure retries one tile, not a batch.
            List<ImageRegion> regions = spark.parallelize(tiles, tiles.size())
                    .map(new RenderTileTask(scene, faults))
                    .collect();
            if (regions.size() != tiles.size()) {
                throw new IllegalStateException(tiles.size() + " tiles were sent but " + regions.size() + " returned");
            }
            ImageWriter image = new ImageWriter("render", bundle.width(), bundle.height());
            regions.forEach(image::writeRegion);
            return image;
        } finally {
            scene.destroy();
        }
    }
}
