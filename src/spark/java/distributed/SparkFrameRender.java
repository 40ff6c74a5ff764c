package distributed;

import cli.RenderOverrides;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.List;
import java.util.concurrent.ExecutionException;
import org.apache.spark.api.java.JavaFutureAction;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import sceneio.CameraPath;
import sceneio.CameraPathLoader;
import sceneio.SceneFileException;

/**
 * An animation rendered on Spark: each frame of a camera path is one task that renders the whole frame on an
 * executor ({@link RenderFrameTask}) and returns it as PNG bytes, which the driver hands to a {@link FrameSink}
 * (the command writes numbered PNG files) as the frames arrive.
 *
 * <p>Each frame is its own small Spark job, and at most twice as many frames as the cluster has cores are in
 * flight: the cores stay busy while the driver holds only a window of frames in memory, never the whole
 * animation (one job collecting every frame would hold them all, and hit {@code spark.driver.maxResultSize}).
 */
public final class SparkFrameRender {
    /** Receives each rendered frame on the driver, in frame order. */
    @FunctionalInterface
    public interface FrameSink {
        void accept(int frame, byte[] png) throws IOException;
    }

    private SparkFrameRender() {}

    /**
     * Renders every frame of the camera path through the scene file, with the command-line overrides. The scene and the path are loaded on the
     * driver first, so a bad file fails with the CLI's message before any task is launched.
     *
     * @return the number of frames rendered
     */
    public static int render(
            JavaSparkContext spark,
            Path sceneFile,
            RenderOverrides overrides,
            Path pathFile,
            FrameSink sink,
            FaultInjection faults)
            throws SceneFileException, IOException {
        SceneBundle bundle = SceneBundle.read(sceneFile, overrides);
        CameraPath path = CameraPathLoader.load(pathFile, bundle.document());
        return render(spark, bundle, path, sink, faults);
    }

    static int render(
            JavaSparkContext spark, SceneBundle bundle, CameraPath path, FrameSink sink, FaultInjection faults)
            throws IOException {
        Broadcast<SceneBundle> scene = spark.broadcast(bundle);
        RenderFrameTask task = new RenderFrameTask(scene, faults);
        int window = Math.max(2, 2 * spark.defaultParallelism());
        ArrayDeque<Pending> inFlight = new ArrayDeque<>();
        try {
            for (int frame = 0; frame < path.frameCount(); frame++) {
                if (inFlight.size() >= window) deliver(inFlight.poll(), sink);
                List<FrameTask> one = List.of(FrameTask.of(frame, path.pose(frame)));
                inFlight.add(
                        new Pending(frame, spark.parallelize(one, 1).map(task).collectAsync()));
            }
            while (!inFlight.isEmpty()) deliver(inFlight.poll(), sink);
        } finally {
            for (Pending pending : inFlight) pending.job().cancel(true);
            scene.destroy();
        }
        return path.frameCount();
    }

    /** A frame's job, submitted and not yet delivered. */
    private record Pending(int frame, JavaFutureAction<List<RenderedFrame>> job) {}

    private static void deliver(Pending pending, FrameSink sink) throws IOException {
        List<RenderedFrame> frames;
        try {
            frames = pending.job().get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for a frame", e);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            String message =
                    String.valueOf(cause.getMessage()).lines().findFirst().orElse("");
            throw new IllegalStateException("frame " + pending.frame() + " could not be rendered: " + message, cause);
        }
        for (RenderedFrame f : frames) sink.accept(f.frame(), f.png());
    }
}
