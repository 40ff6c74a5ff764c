package distributed;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import javax.imageio.ImageIO;
import org.apache.spark.api.java.function.Function;
import org.apache.spark.broadcast.Broadcast;
import renderer.Camera;
import sceneio.CameraPath;

/**
 * The work of one Spark task of an animation (on an executor): load the broadcast scene with the camera moved to
 * the frame's pose, render the whole frame and encode it as PNG. Like a tile, a frame's pixels depend only on the
 * scene and the pose, so a retried or speculative copy returns the same image.
 */
final class RenderFrameTask implements Function<FrameTask, RenderedFrame> {
    private static final long serialVersionUID = 1L;

    private final Broadcast<SceneBundle> scene;
    private final FaultInjection faults;

    RenderFrameTask(Broadcast<SceneBundle> scene, FaultInjection faults) {
        this.scene = scene;
        this.faults = faults;
    }

    @Override
    public RenderedFrame call(FrameTask task) throws Exception {
        Camera camera = scene.value().load(d -> CameraPath.aim(d, task.pose())).camera();
        camera.setThreads(TaskThreads.get());
        camera.renderImage();
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        if (!ImageIO.write(camera.getImage().toBufferedImage(), "png", png)) {
            throw new IOException("no PNG writer is available in this JDK");
        }
        faults.afterRendering("frame", task.frame());
        return new RenderedFrame(task.frame(), png.toByteArray());
    }
}
