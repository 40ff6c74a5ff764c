package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A sphere.
 *
 * @param center its centre (required)
 * @param radius its radius (required, positive)
 */
@JsonPropertyOrder({"center", "radius", "material", "emission"})
public record SphereDocument(Vec3 center, Double radius, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
