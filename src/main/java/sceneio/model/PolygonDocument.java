package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * A convex planar polygon.
 *
 * @param vertices three or more points in order around the outline, all in one plane (required)
 */
@JsonPropertyOrder({"vertices", "material", "emission"})
public record PolygonDocument(List<Vec3> vertices, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
