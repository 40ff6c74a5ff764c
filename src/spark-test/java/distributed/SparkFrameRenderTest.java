package distributed;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cli.RenderOverrides;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.imageio.ImageIO;
import org.apache.spark.api.java.JavaSparkContext;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import sceneio.CameraPath;
import sceneio.CameraPathLoader;
import sceneio.SceneFileException;
import sceneio.SceneLoader;
import sceneio.model.SceneDocument;

/**
 * The frames of a short camera path rendered on Spark (local[2,4], one task per frame) are, pixel for pixel, the
 * images of rendering each frame's camera locally; they arrive in frame order, survive tasks whose first attempt
 * fails, and a bad path file fails before any job.
 */
@ExtendWith(LocalSpark.class)
class SparkFrameRenderTest {
    private static final RenderOverrides NONE = new RenderOverrides();

    private static final String PATH = """
            {
              "interpolation": "smooth",
              "keyframes": [
                {"frame": 0, "location": [0, -300, 170], "target": [0, 0, 20]},
                {"frame": 3, "location": [200, -200, 120], "target": [0, 10, 20]},
                {"frame": 5, "location": [260, 0, 90], "target": [0, 20, 30]}
              ]
            }
            """;

    private static Path scene, path;
    /** The local render of every frame, as the 8-bit pixels written to PNG. */
    private static List<int[]> local;

    @BeforeAll
    static void renderLocally(@TempDir Path dir) throws Exception {
        scene = TestScenes.softShadows(dir, 48, 32);
        path = dir.resolve("orbit.json");
        Files.writeString(path, PATH);
        SceneDocument document = SceneLoader.read(scene);
        CameraPath camera = CameraPathLoader.load(path, document);
        local = new ArrayList<>();
        for (int f = 0; f < camera.frameCount(); f++) {
            BufferedImage image = SceneLoader.build(CameraPath.aim(document, camera.pose(f)), scene)
                    .camera()
                    .renderImage()
                    .getImage()
                    .toBufferedImage();
            local.add(rgb(image));
        }
    }

    private static int[] rgb(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private static int[] decode(byte[] png) throws IOException {
        return rgb(ImageIO.read(new ByteArrayInputStream(png)));
    }

    /** Renders the path on Spark; the frames in the order the sink received them. */
    private static Map<Integer, byte[]> renderOnSpark(JavaSparkContext spark, FaultInjection faults) throws Exception {
        Map<Integer, byte[]> frames = new LinkedHashMap<>();
        int count = SparkFrameRender.render(
                spark,
                scene,
                NONE,
                path,
                (frame, png) -> {
                    assertFalse(frames.containsKey(frame), "frame " + frame + " delivered once");
                    frames.put(frame, png);
                },
                faults);
        assertEquals(6, count);
        return frames;
    }

    @Test
    void theFramesShowTheCameraMoving() {
        assertEquals(6, local.size());
        for (int f = 1; f < local.size(); f++) {
            assertFalse(Arrays.equals(local.get(f - 1), local.get(f)), "frame " + f + " differs from the one before");
        }
    }

    @Test
    void everyFrameMatchesItsLocalRenderInFrameOrder(JavaSparkContext spark) throws Exception {
        Map<Integer, byte[]> frames = renderOnSpark(spark, FaultInjection.NONE);
        assertEquals(List.of(0, 1, 2, 3, 4, 5), List.copyOf(frames.keySet()));
        for (Map.Entry<Integer, byte[]> f : frames.entrySet()) {
            assertArrayEquals(local.get(f.getKey()), decode(f.getValue()), "frame " + f.getKey());
        }
    }

    @Test
    void framesWhoseFirstAttemptFailsAreRetriedIntoTheSameImages(JavaSparkContext spark) throws Exception {
        Map<Integer, byte[]> frames;
        try (TaskEvents events = TaskEvents.attach(spark)) {
            frames = renderOnSpark(spark, new FaultInjection(Set.of(1, 4)));
            events.awaitJobsEnded(6); // one job per frame
            List<String> failed = events.failedTasks();
            assertEquals(2, failed.size(), "frames 1 and 4 failed once each: " + failed);
            assertTrue(failed.stream().allMatch(f -> f.contains("InjectedFailure")), failed.toString());
        }
        for (Map.Entry<Integer, byte[]> f : frames.entrySet()) {
            assertArrayEquals(local.get(f.getKey()), decode(f.getValue()), "frame " + f.getKey());
        }
    }

    @Test
    void aFailureOnTheDriverStopsTheRenderAndSubmitsNoMoreFrames(JavaSparkContext spark) throws Exception {
        List<Integer> delivered = new ArrayList<>();
        try (TaskEvents events = TaskEvents.attach(spark)) {
            IOException e = assertThrows(
                    IOException.class,
                    () -> SparkFrameRender.render(
                            spark,
                            scene,
                            NONE,
                            path,
                            (frame, png) -> {
                                if (frame == 2) throw new IOException("disk full");
                                delivered.add(frame);
                            },
                            FaultInjection.NONE));
            assertEquals("disk full", e.getMessage());
            assertEquals(List.of(0, 1), delivered, "frames before the failure were delivered, none after");
            // local[2]: 4 frames in flight at first, one more after each of frames 0 and 1 was delivered; the
            // frames still in flight when frame 2 failed are cancelled. A control job after them: its start comes
            // after any frame job's start (the scheduler handles submissions in order).
            assertEquals(3, spark.parallelize(List.of(1, 2, 3)).count(), "the context still works");
            events.awaitJobsEnded(7);
            assertEquals(7, events.jobsStarted(), "6 frame jobs and the control job; none after the failure");
        }
    }

    @Test
    void aBadPathFailsOnTheDriverBeforeAnyJob(JavaSparkContext spark) throws Exception {
        // Frame 1 of 0..2 passes through the target: the camera would look at its own location.
        Path bad = path.resolveSibling("through.json");
        Files.writeString(bad, """
                {"keyframes": [
                  {"frame": 0, "location": [0, -100, 20], "target": [0, 0, 20]},
                  {"frame": 2, "location": [0, 100, 20], "target": [0, 0, 20]}]}
                """);
        try (TaskEvents events = TaskEvents.attach(spark)) {
            SceneFileException e = assertThrows(
                    SceneFileException.class,
                    () -> SparkFrameRender.render(spark, scene, NONE, bad, (f, png) -> {}, FaultInjection.NONE));
            assertTrue(e.getMessage().contains("at frame 1 "), e.getMessage());
            assertEquals(3, spark.parallelize(List.of(1, 2, 3)).count());
            events.awaitJobsEnded(1);
            assertEquals(1, events.jobsStarted(), "only the control job ran");
        }
    }
}
