package sceneio.model;

/**
 * The axis of a tube or cylinder: a ray.
 *
 * @param origin where the axis starts (the base centre of a cylinder) (required)
 * @param direction its direction (required, non-zero)
 */
public record AxisDocument(Vec3 origin, Vec3 direction) {}
