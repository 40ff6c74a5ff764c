package distributed;

import java.io.Serializable;
import sceneio.CameraPath;
import sceneio.model.Vec3;

/**
 * One frame of a camera path, as sent to its task: the frame number and the camera's pose, computed on the
 * driver (six doubles travel, not the path).
 */
record FrameTask(int frame, double lx, double ly, double lz, double tx, double ty, double tz) implements Serializable {
    static FrameTask of(int frame, CameraPath.Pose pose) {
        Vec3 l = pose.location(), t = pose.target();
        return new FrameTask(frame, l.x(), l.y(), l.z(), t.x(), t.y(), t.z());
    }

    CameraPath.Pose pose() {
        return new CameraPath.Pose(new Vec3(lx, ly, lz), new Vec3(tx, ty, tz));
    }
}
