package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * A triangle.
 *
 * @param vertices exactly three points, not collinear (required)
 */
@JsonPropertyOrder({"vertices", "material", "emission"})
public record TriangleDocument(List<Vec3> vertices, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
