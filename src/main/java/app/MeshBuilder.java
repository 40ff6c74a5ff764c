package app;

import geometries.Mesh;
import java.util.Arrays;

/**
 * Collects vertices and triangles into the shared arrays of an indexed {@link Mesh}: boxes and quads added here
 * reuse their corner vertices, so a box is 8 vertices and 12 triangles and a lofted surface shares every grid
 * vertex with its four neighbouring quads (which is what makes a mesh watertight).
 */
final class MeshBuilder {
    private double[] vertices = new double[3 * 64];
    private int[] indices = new int[3 * 64];
    private int vertexCount;
    private int indexCount;

    /** Adds a vertex and returns its index. */
    int vertex(double x, double y, double z) {
        if (3 * vertexCount + 3 > vertices.length) vertices = Arrays.copyOf(vertices, 2 * vertices.length);
        vertices[3 * vertexCount] = x;
        vertices[3 * vertexCount + 1] = y;
        vertices[3 * vertexCount + 2] = z;
        return vertexCount++;
    }

    /** Adds the triangle of three vertex indices. */
    void triangle(int a, int b, int c) {
        if (indexCount + 3 > indices.length) indices = Arrays.copyOf(indices, 2 * indices.length);
        indices[indexCount++] = a;
        indices[indexCount++] = b;
        indices[indexCount++] = c;
    }

    /** Adds the quad a-b-c-d (in order around its outline) as two triangles sharing the diagonal a-c. */
    void quad(int a, int b, int c, int d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

    /** Adds an axis-aligned box: 8 shared corners, 12 triangles. */
    void box(double x0, double y0, double z0, double x1, double y1, double z1) {
        int base = vertexCount;
        for (int i = 0; i < 8; i++) {
            vertex((i & 1) == 0 ? x0 : x1, (i & 2) == 0 ? y0 : y1, (i & 4) == 0 ? z0 : z1);
        }
        // Corner i has bit 0 = x, bit 1 = y, bit 2 = z; each face lists its corners around the outline.
        quad(base, base + 2, base + 3, base + 1); // bottom
        quad(base + 4, base + 5, base + 7, base + 6); // top
        quad(base, base + 1, base + 5, base + 4); // y0
        quad(base + 2, base + 6, base + 7, base + 3); // y1
        quad(base, base + 4, base + 6, base + 2); // x0
        quad(base + 1, base + 3, base + 7, base + 5); // x1
    }

    int vertexCount() {
        return vertexCount;
    }

    int triangleCount() {
        return indexCount / 3;
    }

    /** The x, y, z of vertex {@code i}. */
    double coordinate(int i, int axis) {
        return vertices[3 * i + axis];
    }

    /** The mesh of everything added, flat shaded. */
    Mesh build() {
        return new Mesh(Arrays.copyOf(vertices, 3 * vertexCount), Arrays.copyOf(indices, indexCount));
    }

    /**
     * The mesh with smooth shading: each vertex normal is the area-weighted sum of the normals of the triangles
     * around it (the cross product of two edges is twice the area times the unit normal, so summing them is the
     * weighting), oriented consistently when the triangles are wound consistently.
     */
    Mesh buildSmooth() {
        double[] v = Arrays.copyOf(vertices, 3 * vertexCount);
        int[] idx = Arrays.copyOf(indices, indexCount);
        double[] normals = new double[v.length];
        for (int t = 0; t < idx.length; t += 3) {
            int a = 3 * idx[t], b = 3 * idx[t + 1], c = 3 * idx[t + 2];
            double ux = v[b] - v[a], uy = v[b + 1] - v[a + 1], uz = v[b + 2] - v[a + 2];
            double wx = v[c] - v[a], wy = v[c + 1] - v[a + 1], wz = v[c + 2] - v[a + 2];
            double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
            for (int corner : new int[] {a, b, c}) {
                normals[corner] += nx;
                normals[corner + 1] += ny;
                normals[corner + 2] += nz;
            }
        }
        for (int i = 0; i < normals.length; i += 3) {
            if (normals[i] == 0 && normals[i + 1] == 0 && normals[i + 2] == 0) normals[i + 2] = 1; // unused vertex
        }
        return new Mesh(v, idx, normals);
    }
}
