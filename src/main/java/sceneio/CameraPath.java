package sceneio;

import java.util.Arrays;
import sceneio.model.CameraDocument;
import sceneio.model.Interpolation;
import sceneio.model.SceneDocument;
import sceneio.model.Vec3;

/**
 * A checked camera path: keyframed camera locations and targets, interpolated into one {@link Pose} per frame
 * (frames 0 to the last keyframe's). Read it with {@link CameraPathLoader}; {@link #aim} puts a pose into a scene
 * document, which then renders that frame. Poses are pure double arithmetic on the keyframes, so every machine
 * computes the same bits for the same frame.
 */
public final class CameraPath {
    /** The camera of one frame: where it is and the point it looks at. */
    public record Pose(Vec3 location, Vec3 target) {
        /** E.g. {@code location [0.0, -420.0, 160.0], target [0.0, 0.0, 40.0]}, for messages. */
        @Override
        public String toString() {
            return "location " + format(location) + ", target " + format(target);
        }

        private static String format(Vec3 v) {
            return "[" + v.x() + ", " + v.y() + ", " + v.z() + "]";
        }
    }

    private final Interpolation interpolation;
    private final int[] frames;
    private final double[][] locations, targets;

    /**
     * @param frames keyframe frame numbers, strictly increasing from 0
     * @param locations keyframe camera locations, as many as frames
     * @param targets keyframe targets, as many as frames
     */
    CameraPath(Interpolation interpolation, int[] frames, Vec3[] locations, Vec3[] targets) {
        if (frames.length == 0
                || frames[0] != 0
                || frames.length != locations.length
                || frames.length != targets.length) {
            throw new IllegalArgumentException("a camera path needs keyframes starting at frame 0");
        }
        for (int k = 1; k < frames.length; k++) {
            if (frames[k] <= frames[k - 1]) throw new IllegalArgumentException("keyframes must be in frame order");
        }
        this.interpolation = interpolation;
        this.frames = frames.clone();
        this.locations = Arrays.stream(locations).map(CameraPath::array).toArray(double[][]::new);
        this.targets = Arrays.stream(targets).map(CameraPath::array).toArray(double[][]::new);
    }

    private static double[] array(Vec3 v) {
        return new double[] {v.x(), v.y(), v.z()};
    }

    /**
     * How the camera moves between keyframes.
     *
     * @return the interpolation between keyframes: linear or smooth (Catmull-Rom), never null
     */
    public Interpolation getInterpolation() {
        return interpolation;
    }

    /**
     * The number of frames: the last keyframe's frame + 1.
     *
     * @return the number of frames, at least 1
     */
    public int frameCount() {
        return frames[frames.length - 1] + 1;
    }

    /**
     * The camera of {@code frame}; exactly the keyframe's values on a keyframe.
     *
     * @param frame the 0-based frame number, from 0 to {@link #frameCount()} - 1
     * @return the camera location and target at that frame
     * @throws IllegalArgumentException if {@code frame} is outside the path
     */
    public Pose pose(int frame) {
        if (frame < 0 || frame >= frameCount()) {
            throw new IllegalArgumentException("frame " + frame + " is not in the path's 0.." + (frameCount() - 1));
        }
        int k = segment(frame);
        return new Pose(interpolate(locations, k, frame), interpolate(targets, k, frame));
    }

    /** The keyframe index k with frames[k] <= frame, and frame < frames[k + 1] unless k is the last. */
    private int segment(int frame) {
        int k = Arrays.binarySearch(frames, frame);
        return k >= 0 ? k : -k - 2;
    }

    private Vec3 interpolate(double[][] p, int k, int frame) {
        if (frame == frames[k]) return new Vec3(p[k][0], p[k][1], p[k][2]);
        double span = frames[k + 1] - frames[k];
        double t = (frame - frames[k]) / span;
        double[] out = new double[3];
        if (interpolation == Interpolation.LINEAR) {
            for (int i = 0; i < 3; i++) out[i] = p[k][i] + t * (p[k + 1][i] - p[k][i]);
        } else {
            // Cubic Hermite with Catmull-Rom tangents for uneven keyframe spacing (per frame, times the span):
            // the curve passes through every keyframe with a continuous velocity.
            double h00 = (2 * t - 3) * t * t + 1, h10 = ((t - 2) * t + 1) * t, h01 = (3 - 2 * t) * t * t;
            double h11 = (t - 1) * t * t;
            for (int i = 0; i < 3; i++) {
                out[i] = h00 * p[k][i]
                        + h10 * span * tangent(p, k, i)
                        + h01 * p[k + 1][i]
                        + h11 * span * tangent(p, k + 1, i);
            }
        }
        return new Vec3(out[0], out[1], out[2]);
    }

    /** The velocity (per frame) at keyframe k: the central difference of its neighbours, one-sided at the ends. */
    private double tangent(double[][] p, int k, int i) {
        int a = Math.max(k - 1, 0), b = Math.min(k + 1, frames.length - 1);
        return (p[b][i] - p[a][i]) / (frames[b] - frames[a]);
    }

    /**
     * The scene with its camera moved to {@code pose}: location and {@code lookAt} replaced, everything else
     * (up, view plane, depth of field) kept. Build it with {@link SceneLoader#build} to render the frame.
     *
     * @param scene the scene document whose camera is moved; not null
     * @param pose the camera location and the point it looks at
     * @return a copy of {@code scene} with the camera moved (a camera is created from the pose if the scene has none)
     */
    public static SceneDocument aim(SceneDocument scene, Pose pose) {
        CameraDocument c = scene.camera();
        CameraDocument moved = c == null
                ? new CameraDocument(pose.location(), pose.target(), null, null, null, null, null, null)
                : new CameraDocument(
                        pose.location(),
                        pose.target(),
                        null,
                        c.up(),
                        c.vpDistance(),
                        c.vpWidth(),
                        c.vpHeight(),
                        c.depthOfField());
        return scene.withCamera(moved);
    }
}
