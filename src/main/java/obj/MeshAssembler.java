package obj;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Turns the corners an OBJ file's faces list (a position, a texture coordinate and a normal index each, OBJ's
 * separate index streams) into meshes of unified vertices, one per material: every distinct combination a part
 * uses becomes one vertex of that part. Normals (texture coordinates) are kept for a part only if every corner of
 * it has one, since a mesh has them for all vertices or none.
 */
final class MeshAssembler {
    private final String file;
    private final DoubleList positions, normals, texCoords;
    private final IntList cornerVertices, cornerNormals, cornerTexCoords, triangleMaterials;
    private final List<String> materials;

    MeshAssembler(
            String file,
            DoubleList positions,
            DoubleList normals,
            DoubleList texCoords,
            IntList cornerVertices,
            IntList cornerNormals,
            IntList cornerTexCoords,
            IntList triangleMaterials,
            List<String> materials) {
        this.file = file;
        this.positions = positions;
        this.normals = normals;
        this.texCoords = texCoords;
        this.cornerVertices = cornerVertices;
        this.cornerNormals = cornerNormals;
        this.cornerTexCoords = cornerTexCoords;
        this.triangleMaterials = triangleMaterials;
        this.materials = materials;
    }

    /** One mesh per material in order of first use; warnings about dropped normals or texture coordinates added. */
    List<ObjMesh> parts(List<String> warnings) {
        int triangles = triangleMaterials.size(), count = materials.size();
        // The triangles grouped by material in one pass (a counting sort): a file switching materials often must
        // not cost materials x triangles.
        int[] start = new int[count + 1];
        for (int t = 0; t < triangles; t++) start[triangleMaterials.get(t) + 1]++;
        for (int m = 0; m < count; m++) start[m + 1] += start[m];
        int[] order = new int[triangles];
        int[] next = Arrays.copyOf(start, count);
        for (int t = 0; t < triangles; t++) order[next[triangleMaterials.get(t)]++] = t;
        List<ObjMesh> parts = new ArrayList<>();
        boolean droppedNormals = false, droppedTexCoords = false;
        for (int m = 0; m < count; m++) {
            int[] corners = new int[3 * (start[m + 1] - start[m])];
            int k = 0;
            for (int i = start[m]; i < start[m + 1]; i++) {
                int t = order[i];
                corners[k++] = 3 * t;
                corners[k++] = 3 * t + 1;
                corners[k++] = 3 * t + 2;
            }
            boolean allNormals = true, anyNormals = false, allTexCoords = true, anyTexCoords = false;
            for (int c : corners) {
                int n = cornerNormals.get(c);
                allNormals &= n >= 0 && !normals.isZero(n);
                anyNormals |= n >= 0;
                allTexCoords &= cornerTexCoords.get(c) >= 0;
                anyTexCoords |= cornerTexCoords.get(c) >= 0;
            }
            // A part without any normals (texture coordinates) is flat (untextured) by design: no warning.
            droppedNormals |= !allNormals && anyNormals;
            droppedTexCoords |= !allTexCoords && anyTexCoords;
            parts.add(part(corners, allNormals, allTexCoords, materials.get(m), materials.size() == 1));
        }
        if (droppedNormals) {
            warnings.add(file + ": normals ignored (flat shading): some face corners have no normal or a zero one");
        }
        if (droppedTexCoords) {
            warnings.add(file + ": texture coordinates ignored (texture maps show one texel): some face corners"
                    + " have none");
        }
        return parts;
    }

    /** A corner as a vertex of a part: what makes two corners the same vertex. */
    private record Corner(int position, int texCoord, int normal) {}

    private ObjMesh part(int[] corners, boolean withNormals, boolean withTexCoords, String material, boolean whole) {
        if (whole && !withNormals && !withTexCoords) {
            // The file's positions as they are (unused ones included), as a plain OBJ mesh always was read.
            int[] indices = new int[corners.length];
            for (int i = 0; i < indices.length; i++) indices[i] = cornerVertices.get(corners[i]);
            return new ObjMesh(positions.toArray(), indices, null, null, material, List.of());
        }
        Map<Corner, Integer> vertices = new HashMap<>();
        DoubleList v = new DoubleList(), n = new DoubleList(), uv = new DoubleList();
        int[] indices = new int[corners.length];
        for (int i = 0; i < corners.length; i++) {
            int c = corners[i];
            int vi = cornerVertices.get(c);
            int ni = withNormals ? cornerNormals.get(c) : -1;
            int ti = withTexCoords ? cornerTexCoords.get(c) : -1;
            Corner key = new Corner(vi, ti, ni);
            Integer index = vertices.get(key);
            if (index == null) {
                index = vertices.size();
                vertices.put(key, index);
                for (int k = 0; k < 3; k++) v.add(positions.get(3 * vi + k));
                if (withNormals) for (int k = 0; k < 3; k++) n.add(normals.get(3 * ni + k));
                if (withTexCoords) for (int k = 0; k < 2; k++) uv.add(texCoords.get(2 * ti + k));
            }
            indices[i] = index;
        }
        return new ObjMesh(
                v.toArray(),
                indices,
                withNormals ? n.toArray() : null,
                withTexCoords ? uv.toArray() : null,
                material,
                List.of());
    }

    /** The parts of {@code model} as one mesh (concatenated), with the model's warnings. */
    static ObjMesh merged(ObjModel model) {
        List<ObjMesh> parts = model.parts();
        if (parts.size() == 1) {
            ObjMesh p = parts.get(0);
            return new ObjMesh(p.vertices(), p.indices(), p.normals(), p.texCoords(), null, model.warnings());
        }
        // Only in readModel's by-material mode are there several parts; read() keeps one.
        int vertexCount = 0, indexCount = 0;
        boolean normals = true, texCoords = true;
        for (ObjMesh p : parts) {
            vertexCount += p.vertexCount();
            indexCount += p.indices().length;
            normals &= p.normals() != null;
            texCoords &= p.texCoords() != null;
        }
        double[] v = new double[3 * vertexCount];
        double[] n = normals ? new double[3 * vertexCount] : null;
        double[] uv = texCoords ? new double[2 * vertexCount] : null;
        int[] indices = new int[indexCount];
        int vo = 0, io = 0;
        for (ObjMesh p : parts) {
            System.arraycopy(p.vertices(), 0, v, 3 * vo, p.vertices().length);
            if (n != null) System.arraycopy(p.normals(), 0, n, 3 * vo, p.normals().length);
            if (uv != null) System.arraycopy(p.texCoords(), 0, uv, 2 * vo, p.texCoords().length);
            for (int index : p.indices()) indices[io++] = index + vo;
            vo += p.vertexCount();
        }
        return new ObjMesh(v, Arrays.copyOf(indices, io), n, uv, null, model.warnings());
    }
}
