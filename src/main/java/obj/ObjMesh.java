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
    public ObjMesh {
        warnings = List.copyOf(warnings);
    }

    public int vertexCount() {
        return vertices.length / 3;
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    /** A mesh geometry of these triangles, smooth-shaded by the file's normals if {@code smooth} and present. */
    public Mesh toMesh(boolean smooth) {
        return new Mesh(vertices, indices, smooth ? normals : null);
    }
}
