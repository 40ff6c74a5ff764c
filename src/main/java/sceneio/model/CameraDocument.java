package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * The camera: its location, where it looks (a {@code lookAt} point or a {@code direction}, exactly one), the up
 * direction and the view plane (distance and size in scene units), with optional depth of field.
 *
 * @param location the camera position (required)
 * @param lookAt a point to aim at, or null when {@code direction} is given
 * @param direction the view direction, or null when {@code lookAt} is given
 * @param up the up direction (default +Z, or +Y when looking along Z; need not be perpendicular to the view)
 * @param vpDistance distance from the camera to the view plane (required, positive)
 * @param vpWidth view plane width (required, positive)
 * @param vpHeight view plane height (required, positive)
 * @param depthOfField a thin lens, or null for a pinhole camera
 */
@JsonPropertyOrder({"location", "lookAt", "direction", "up", "vpDistance", "vpWidth", "vpHeight", "depthOfField"})
public record CameraDocument(
        Vec3 location,
        Vec3 lookAt,
        Vec3 direction,
        Vec3 up,
        Double vpDistance,
        Double vpWidth,
        Double vpHeight,
        DepthOfFieldDocument depthOfField) {

    /**
     * This camera with another view plane height (used to keep pixels square when the resolution changes).
     *
     * @param vpHeight the new view plane height in scene units, or null when absent
     * @return a copy of this camera document with only the view plane height replaced
     */
    public CameraDocument withVpHeight(Double vpHeight) {
        return new CameraDocument(location, lookAt, direction, up, vpDistance, vpWidth, vpHeight, depthOfField);
    }
}
