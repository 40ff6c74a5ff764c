package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A triangle mesh from a Wavefront OBJ file, placed by a uniform scale then a translation. Its faces take the
 * materials of the OBJ's {@code usemtl} and {@code mtllib} (MTL files), unless {@code material} overrides them all
 * or {@code materials} single ones.
 *
 * @param file path of the OBJ file relative to the scene file's folder (required)
 * @param scale uniform scale, positive (default 1)
 * @param translate offset added after scaling (default [0, 0, 0])
 * @param smooth shade with the file's vertex normals when it has them (default true)
 * @param material the material of every face, overriding the OBJ's materials, or null
 * @param emission the emission of every face, overriding MTL {@code Ke}, or null
 * @param materials materials by OBJ material name ({@code usemtl}), overriding the MTL's, or null
 */
@JsonPropertyOrder({"file", "scale", "translate", "smooth", "material", "emission", "materials"})
public record MeshDocument(
        String file,
        Double scale,
        Vec3 translate,
        Boolean smooth,
        MaterialRef material,
        Vec3 emission,
        java.util.Map<String, MaterialRef> materials)
        implements GeometryDocument, SurfaceDocument {
    /**
     * A mesh without per-material overrides.
     *
     * @param file path of the OBJ file relative to the scene file's folder (required)
     * @param scale uniform scale, positive (default 1)
     * @param translate offset added after scaling (default [0, 0, 0])
     * @param smooth shade with the file's vertex normals when it has them (default true)
     * @param material the material of every face, overriding the OBJ's materials, or null
     * @param emission the emission of every face, overriding MTL {@code Ke}, or null
     */
    public MeshDocument(
            String file, Double scale, Vec3 translate, Boolean smooth, MaterialRef material, Vec3 emission) {
        this(file, scale, translate, smooth, material, emission, null);
    }
}
