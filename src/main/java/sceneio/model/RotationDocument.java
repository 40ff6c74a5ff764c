package sceneio.model;

/**
 * A rotation about an axis through the origin, counter-clockwise seen from the axis tip.
 *
 * @param axis the axis (required, non-zero)
 * @param degrees the angle in degrees (required)
 */
public record RotationDocument(Vec3 axis, Double degrees) {}
