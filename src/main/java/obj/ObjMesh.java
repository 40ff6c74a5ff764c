package obj;

import geometries.Mesh;
import java.util.List;

/**
 * The triangles read from an OBJ file as flat arrays, ready for {@link Mesh}: x, y, z per vertex, three vertex
 * indices per triangle (0-based) and optionally a normal per vertex. Also the warnings about statements that
 * were skipped, one per kind.
 *
 * @param vertices x, y, z of each vertex
 * @param indices three 0-based vertex indices per triangle
 * @param normals x, y, z of a normal per vertex, or null when the file has none for some face corner
 * @param warnings one line per kind of skipped statement, in order of first appearance
 */
public record ObjMesh(double[] vertices, int[] indices, double[] normals, List<String> warnings) {
    /**
     * Copies the warnings into an unmodifiable list.
     *
     * @param vertices x, y, z of each vertex
     * @param indices three 0-based vertex indices per triangle
     * @param normals x, y, z of a normal per vertex, or null
     * @param warnings one line per kind of skipped statement; not null, no null element
     */
    public ObjMesh {
        warnings = List.copyOf(warnings);
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
     * A mesh geometry of these triangles, smooth-shaded by the file's normals if {@code smooth} and present.
     *
     * @param smooth true to interpolate the file's normals (when it has them), false for flat shading
     * @return a new mesh sharing this record's arrays
     */
    public Mesh toMesh(boolean smooth) {
        return new Mesh(vertices, indices, smooth ? normals : null);
    }
}
