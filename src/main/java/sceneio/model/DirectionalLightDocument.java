package sceneio.model;

/**
 * Light from infinitely far away along one direction.
 *
 * @param color RGB intensity (required)
 * @param direction the direction the light travels (required, non-zero)
 */
public record DirectionalLightDocument(Vec3 color, Vec3 direction) implements LightDocument {}
