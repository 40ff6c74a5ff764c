package distributed;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cli.RenderOverrides;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.apache.spark.api.java.JavaSparkContext;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import renderer.ImageWriter;
import sceneio.SceneFileException;
import sceneio.SceneLoader;

/**
 * A still rendered as tiles on Spark (local[2,4]) is bit-identical, in linear floating point, to
 * {@code Camera.renderImage()} of the same scene file on one machine: for several tile grids, with tasks whose
 * first attempt fails after rendering (so tiles are rendered twice), and a bad scene fails before any job.
 */
@ExtendWith(LocalSpark.class)
class SparkTileRenderTest {
    private static final RenderOverrides NONE = new RenderOverrides();

    private static Path scene;
    private static ImageWriter local;

    @BeforeAll
    static void renderLocally(@TempDir Path dir) throws Exception {
        scene = TestScenes.softShadows(dir, 90, 60);
        local = TestScenes.renderLocally(scene);
    }

    @Test
    void theLocalImageIsVaried() {
        long distinct = 0;
        for (int y = 0; y < local.getNy(); y++) {
            for (int x = 1; x < local.getNx(); x++) {
                if (!local.getPixel(x, y).equals(local.getPixel(x - 1, y))) distinct++;
            }
        }
        assertTrue(distinct > local.getNx() * local.getNy() / 2, "a misplaced tile would show: " + distinct);
    }

    @Test
    void fourAndSixteenTilesAreBitIdenticalToTheLocalRender(JavaSparkContext spark) throws Exception {
        for (String tiles : List.of("4", "16")) {
            ImageWriter image = SparkTileRender.render(spark, scene, NONE, TileGrid.parse(tiles), FaultInjection.NONE);
            assertEquals(List.of(), TestScenes.differences(local, image), tiles + " tiles");
        }
    }

    @Test
    void unevenTilesAreBitIdenticalToo(JavaSparkContext spark) throws Exception {
        // 7 x 3 tiles of 12 or 13 by 20 pixels: edges that are neither multiples of 16 nor equal.
        ImageWriter image = SparkTileRender.render(spark, scene, NONE, new TileGrid(7, 3), FaultInjection.NONE);
        assertEquals(List.of(), TestScenes.differences(local, image));
    }

    @Test
    void commandLineOverridesAreAppliedOnTheExecutorsAsLocally(JavaSparkContext spark) throws Exception {
        // Another size (both given: the view plane keeps square pixels), one sample per pixel, brute force.
        RenderOverrides overrides = RenderOverrides.of(50, 40, 1, false);
        ImageWriter expected = SceneLoader.build(overrides.apply(SceneLoader.read(scene)), scene)
                .camera()
                .renderImage()
                .getImage();
        ImageWriter image = SparkTileRender.render(spark, scene, overrides, new TileGrid(3, 2), FaultInjection.NONE);
        assertEquals(50, image.getNx());
        assertEquals(40, image.getNy());
        assertEquals(List.of(), TestScenes.differences(expected, image));
    }

    @Test
    void tasksWhoseFirstAttemptFailsAreRetriedIntoTheSameImage(JavaSparkContext spark) throws Exception {
        ImageWriter image;
        try (TaskEvents events = TaskEvents.attach(spark)) {
            image = SparkTileRender.render(spark, scene, NONE, new TileGrid(2, 2), new FaultInjection(Set.of(0, 3)));
            events.awaitJobsEnded(1);
            List<String> failed = events.failedTasks();
            assertEquals(2, failed.size(), "tiles 0 and 3 failed once each: " + failed);
            for (String f : failed) {
                assertTrue(f.startsWith("distributed.FaultInjection$InjectedFailure: injected failure"), f);
            }
        }
        assertEquals(List.of(), TestScenes.differences(local, image));
    }

    @Test
    void aBadSceneFailsOnTheDriverBeforeAnyJob(JavaSparkContext spark) throws Exception {
        Path bad = scene.resolveSibling("bad-radius.json");
        Files.writeString(bad, Files.readString(scene).replace("\"radius\": 4,", "\"radius\": -4,"));
        try (TaskEvents events = TaskEvents.attach(spark)) {
            SceneFileException e = assertThrows(
                    SceneFileException.class,
                    () -> SparkTileRender.render(spark, bad, NONE, new TileGrid(2, 2), FaultInjection.NONE));
            assertTrue(e.getMessage().contains("$.geometries[3].radius"), e.getMessage());
            // A job after the failure: once its end is seen, every earlier event has been too.
            assertEquals(3, spark.parallelize(List.of(1, 2, 3)).count());
            events.awaitJobsEnded(1);
            assertEquals(1, events.jobsStarted(), "only the control job ran");
        }
    }
}
