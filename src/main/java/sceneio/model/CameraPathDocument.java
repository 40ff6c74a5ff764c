package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * A camera path file as written: keyframes of the camera's location and target, interpolated into one pose per
 * frame (docs/SPARK.md). The frames are 0 up to the last keyframe's frame.
 *
 * @param version the format version; absent or 1
 * @param interpolation how to move between keyframes (default linear)
 * @param keyframes the keyframes in increasing frame order, the first at frame 0 (required, at least one)
 */
@JsonPropertyOrder({"version", "interpolation", "keyframes"})
public record CameraPathDocument(Integer version, Interpolation interpolation, List<KeyframeDocument> keyframes) {}
