package sceneio.model;

/** How a camera path moves between its keyframes. */
public enum Interpolation {
    /** Straight lines at constant speed from one keyframe to the next (the motion turns sharply at keyframes). */
    LINEAR,
    /**
     * A Catmull-Rom spline through the keyframes: the velocity is continuous, so the camera glides through them
     * instead of turning sharply. With two keyframes it is the straight line.
     */
    SMOOTH
}
