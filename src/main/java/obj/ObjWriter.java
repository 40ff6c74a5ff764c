package obj;

import geometries.Mesh;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Writes a {@link Mesh} as a Wavefront OBJ file that {@link ObjReader} reads back to the same doubles: {@code v}
 * and, for smooth meshes, {@code vn} lines, for meshes with texture coordinates {@code vt} lines, with shortest
 * round-trip decimals, then one {@code f} per triangle.
 */
public final class ObjWriter {
    private ObjWriter() {}

    /**
     * The OBJ text of {@code mesh}.
     *
     * @param mesh the mesh to write
     * @param comment a one-line comment written first as {@code # comment} (line breaks become spaces), or null for
     *     none
     * @return the OBJ text, one statement per line
     */
    public static String toObj(Mesh mesh, String comment) {
        double[] v = mesh.getVertices();
        int[] f = mesh.getIndices();
        double[] n = mesh.getNormals();
        double[] uv = mesh.getTexCoords();
        StringBuilder s = new StringBuilder(32 * (v.length + f.length));
        if (comment != null) s.append("# ").append(comment.replace('\n', ' ')).append('\n');
        for (int i = 0; i < v.length; i += 3) {
            s.append("v ")
                    .append(v[i])
                    .append(' ')
                    .append(v[i + 1])
                    .append(' ')
                    .append(v[i + 2])
                    .append('\n');
        }
        if (n != null) {
            for (int i = 0; i < n.length; i += 3) {
                s.append("vn ")
                        .append(n[i])
                        .append(' ')
                        .append(n[i + 1])
                        .append(' ')
                        .append(n[i + 2])
                        .append('\n');
            }
        }
        if (uv != null) {
            for (int i = 0; i < uv.length; i += 2) {
                s.append("vt ").append(uv[i]).append(' ').append(uv[i + 1]).append('\n');
            }
        }
        for (int i = 0; i < f.length; i += 3) {
            s.append('f');
            for (int k = 0; k < 3; k++) {
                int index = f[i + k] + 1; // OBJ counts from 1
                s.append(' ').append(index);
                if (uv != null) s.append('/').append(index);
                if (n != null) s.append(uv != null ? "/" : "//").append(index);
            }
            s.append('\n');
        }
        return s.toString();
    }

    /**
     * Writes {@code mesh} to {@code file} through a temporary file moved into place.
     *
     * @param mesh the mesh to write
     * @param file the file to create or replace
     * @param comment a one-line comment written first, or null for none
     */
    public static void write(Mesh mesh, Path file, String comment) {
        String text = toObj(mesh, comment);
        renderer.AtomicFile.write(file, "OBJ file", temp -> Files.writeString(temp, text, StandardCharsets.UTF_8));
    }
}
