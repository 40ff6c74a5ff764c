package obj;

import geometries.Mesh;
import java.util.List;

/**
 * Triangles read from an OBJ file as flat arrays, ready for {@link Mesh}: x, y, z per vertex, three vertex indices
 * per triangle (0-based), optionally a normal and texture coordinates per vertex, and the name of the OBJ material
 * ({@code usemtl}) the faces use. Also the warnings about statements that were skipped, one per kind.
 *
 * @param vertices x, y, z of each vertex
 * @param indices three 0-based vertex indices per triangle
 * @param normals x, y, z of a normal per vertex, or null when the file has none for some face corner
 * @param texCoords u, v per vertex, or null when the file has none for some face corner
 * @param material the {@code usemtl} name of these faces, or null for faces before any {@code usemtl}
 * @param warnings one line per kind of skipped statement, in order of first appearance
 */
public record ObjMesh(
        double[] vertices,
        int[] indices,
        double[] normals,
        double[] texCoords,
        String material,
        List<String> warnings) {
    /**
     * Copies the warnings into an unmodifiable list.
     *
     * @param vertices x, y, z of each vertex
     * @param indices three 0-based vertex indices per triangle
     * @param normals x, y, z of a normal per vertex, or null
     * @param texCoords u, v per vertex, or null
     * @param material the {@code usemtl} name, or null
     * @param warnings one line per kind of skipped statement; not null, no null element
     */
    public ObjMesh {
        warnings = List.copyOf(warnings);
    }

    /**
     * Triangles without texture coordinates or material.
     *
     * @param vertices x, y, z of each vertex
     * @param indices three 0-based vertex indices per triangle
     * @param normals x, y, z of a normal per vertex, or null
     * @param warnings one line per kind of skipped statement; not null, no null element
     */
    public ObjMesh(double[] vertices, int[] indices, double[] normals, List<String> warnings) {
        this(vertices, indices, normals, null, null, warnings);
    }

    /**
     * The number of vertices.
     *
     * @return the vertex count, a third of the length of {@link #vertices()}
     */
    public int vertexCount() {
        return vertices.length / 3;
    }

    /**
     * The number of triangles.
     *
     * @return the triangle count, a third of the length of {@link #indices()}
     */
    public int triangleCount() {
        return indices.length / 3;
    }

    /**
     * A mesh geometry of these triangles, smooth-shaded by the file's normals if {@code smooth} and present, with
     * the texture coordinates when present.
     *
     * @param smooth true to interpolate the file's normals (when it has them), false for flat shading
     * @return a new mesh
     */
    public Mesh toMesh(boolean smooth) {
        return new Mesh(vertices, indices, smooth ? normals : null, texCoords);
    }
}
