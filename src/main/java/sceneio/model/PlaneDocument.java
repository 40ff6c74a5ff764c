package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * An infinite plane.
 *
 * @param point a point on it (required)
 * @param normal its normal (required, non-zero)
 */
@JsonPropertyOrder({"point", "normal", "material", "emission"})
public record PlaneDocument(Vec3 point, Vec3 normal, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
