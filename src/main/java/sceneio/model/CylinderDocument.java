package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A capped cylinder from the axis origin along the axis direction.
 *
 * @param radius its radius (required, positive)
 * @param axis its axis; the origin is the centre of the base (required)
 * @param height its height (required, positive)
 */
@JsonPropertyOrder({"radius", "axis", "height", "material", "emission"})
public record CylinderDocument(Double radius, AxisDocument axis, Double height, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
