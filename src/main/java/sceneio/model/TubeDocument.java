package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * An infinite tube around an axis.
 *
 * @param radius its radius (required, positive)
 * @param axis its axis (required)
 */
@JsonPropertyOrder({"radius", "axis", "material", "emission"})
public record TubeDocument(Double radius, AxisDocument axis, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
