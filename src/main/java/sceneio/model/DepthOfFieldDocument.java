package sceneio.model;

/**
 * A thin lens: objects at {@code focalDistance} along the view direction are sharp, others blur with the
 * aperture.
 *
 * @param focalDistance distance of the sharp plane (required, positive)
 * @param aperture lens radius (required, zero or positive)
 * @param samples lens rays per pixel sample (default 16)
 */
public record DepthOfFieldDocument(Double focalDistance, Double aperture, Integer samples) {}
