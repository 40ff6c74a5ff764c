package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A triangle mesh from a Wavefront OBJ file, placed by a uniform scale then a translation.
 *
 * @param file path of the OBJ file relative to the scene file's folder (required)
 * @param scale uniform scale, positive (default 1)
 * @param translate offset added after scaling (default [0, 0, 0])
 * @param smooth shade with the file's vertex normals when it has them (default true)
 */
@JsonPropertyOrder({"file", "scale", "translate", "smooth", "material", "emission"})
public record MeshDocument(
        String file, Double scale, Vec3 translate, Boolean smooth, MaterialRef material, Vec3 emission)
        implements GeometryDocument, SurfaceDocument {}
