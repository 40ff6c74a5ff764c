package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * Where the camera is and what it looks at on one frame of a camera path.
 *
 * @param frame the frame number, from 0 (required)
 * @param location the camera position (required)
 * @param target the point the camera looks at (required, not the location)
 */
@JsonPropertyOrder({"frame", "location", "target"})
public record KeyframeDocument(Integer frame, Vec3 location, Vec3 target) {}
