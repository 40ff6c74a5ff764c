package geometries;

import java.util.Arrays;

/**
 * Procedural triangle meshes for benchmarks, tests and demo scenes: a wavy heightfield and a subdivided
 * icosahedron. Both are built straight into the flat vertex and index arrays of a {@link Mesh}, so a million
 * triangles take a fraction of a second.
 */
public final class Meshes {
    private Meshes() {}

    /**
     * An {@code n x n} grid of quads over {@code [-1, 1]^2}, two triangles per quad, lifted to the height
     * {@code z = 0.15 sin(3x) cos(2y) + 0.05 sin(11x + 1) sin(13y + 2) + 0.02 sin(37x) cos(41y)}. Triangles wind
     * counter-clockwise seen from +z. {@code n = 224} gives 100,352 triangles, {@code n = 708} gives 1,002,528.
     *
     * @param n the number of quads per side, 1 to 16,384
     * @return a new mesh of {@code 2 n^2} triangles
     * @throws IllegalArgumentException if {@code n} is out of range
     */
    public static Mesh heightfield(int n) {
        if (n < 1 || n > 16_384) {
            throw new IllegalArgumentException("heightfield size must be in [1, 16384] quads, but was " + n);
        }
        int side = n + 1;
        double[] vertices = new double[3 * side * side];
        for (int j = 0; j < side; j++) {
            double y = -1 + 2.0 * j / n;
            for (int i = 0; i < side; i++) {
                double x = -1 + 2.0 * i / n;
                int o = 3 * (j * side + i);
                vertices[o] = x;
                vertices[o + 1] = y;
                vertices[o + 2] = height(x, y);
            }
        }
        int[] indices = new int[6 * n * n];
        int o = 0;
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int v00 = j * side + i, v10 = v00 + 1, v01 = v00 + side, v11 = v01 + 1;
                indices[o++] = v00;
                indices[o++] = v10;
                indices[o++] = v11;
                indices[o++] = v00;
                indices[o++] = v11;
                indices[o++] = v01;
            }
        }
        return new Mesh(vertices, indices);
    }

    /**
     * The heightfield's surface height above {@code (x, y)}.
     *
     * @param x the x coordinate, in [-1, 1] on the mesh
     * @param y the y coordinate, in [-1, 1] on the mesh
     * @return the height z
     */
    public static double height(double x, double y) {
        return 0.15 * Math.sin(3 * x) * Math.cos(2 * y)
                + 0.05 * Math.sin(11 * x + 1) * Math.sin(13 * y + 2)
                + 0.02 * Math.sin(37 * x) * Math.cos(41 * y);
    }

    /**
     * A unit icosahedron subdivided {@code level} times, each triangle split into four at its edge midpoints and
     * the new vertices projected onto the unit sphere. Vertices are shared, so the mesh is closed; triangles wind
     * counter-clockwise seen from outside. Level 6 gives 81,920 triangles, level 8 gives 1,310,720.
     *
     * @param level the subdivision level, 0 to 10
     * @return a new mesh of {@code 20 * 4^level} triangles
     * @throws IllegalArgumentException if {@code level} is out of range
     */
    public static Mesh icosphere(int level) {
        if (level < 0 || level > 10) {
            throw new IllegalArgumentException("icosphere level must be in [0, 10], but was " + level);
        }
        double t = (1 + Math.sqrt(5)) / 2;
        double[] base = {
            -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0,
            -1, -t, 0, 1
        };
        int[] indices = {
            0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4,
            3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1
        };
        // V = 10 * 4^level + 2 for a subdivided icosahedron (Euler's formula with E = 3F/2).
        int finalVertices = 10 * (1 << (2 * level)) + 2;
        double[] vertices = new double[3 * finalVertices];
        int vertexCount = 12;
        for (int v = 0; v < 12; v++) {
            normalizeInto(vertices, v, base[3 * v], base[3 * v + 1], base[3 * v + 2]);
        }
        for (int l = 0; l < level; l++) {
            int triangles = indices.length / 3;
            int[] next = new int[12 * triangles];
            // Each edge is met by two triangles; the table hands both the same midpoint vertex.
            EdgeMidpoints midpoints = new EdgeMidpoints(3 * triangles / 2);
            for (int f = 0; f < triangles; f++) {
                int a = indices[3 * f], b = indices[3 * f + 1], c = indices[3 * f + 2];
                int ab = midpoints.get(a, b, vertexCount);
                if (ab == vertexCount) vertexCount = addMidpoint(vertices, vertexCount, a, b);
                int bc = midpoints.get(b, c, vertexCount);
                if (bc == vertexCount) vertexCount = addMidpoint(vertices, vertexCount, b, c);
                int ca = midpoints.get(c, a, vertexCount);
                if (ca == vertexCount) vertexCount = addMidpoint(vertices, vertexCount, c, a);
                int o = 12 * f;
                next[o] = a;
                next[o + 1] = ab;
                next[o + 2] = ca;
                next[o + 3] = b;
                next[o + 4] = bc;
                next[o + 5] = ab;
                next[o + 6] = c;
                next[o + 7] = ca;
                next[o + 8] = bc;
                next[o + 9] = ab;
                next[o + 10] = bc;
                next[o + 11] = ca;
            }
            indices = next;
        }
        return new Mesh(Arrays.copyOf(vertices, 3 * vertexCount), indices);
    }

    private static int addMidpoint(double[] vertices, int count, int a, int b) {
        normalizeInto(
                vertices,
                count,
                vertices[3 * a] + vertices[3 * b],
                vertices[3 * a + 1] + vertices[3 * b + 1],
                vertices[3 * a + 2] + vertices[3 * b + 2]);
        return count + 1;
    }

    private static void normalizeInto(double[] vertices, int v, double x, double y, double z) {
        double scale = 1 / Math.sqrt(x * x + y * y + z * z);
        vertices[3 * v] = x * scale;
        vertices[3 * v + 1] = y * scale;
        vertices[3 * v + 2] = z * scale;
    }

    /** An open-addressing table from an undirected edge (two vertex indices) to its midpoint vertex. */
    private static final class EdgeMidpoints {
        private final long[] keys;
        private final int[] values;
        private final int mask;

        EdgeMidpoints(int edges) {
            int capacity = Integer.highestOneBit(Math.max(4, 2 * edges)) << 1;
            keys = new long[capacity];
            Arrays.fill(keys, -1);
            values = new int[capacity];
            mask = capacity - 1;
        }

        /** The midpoint of edge (a, b); if the edge is new, records {@code fresh} and returns it. */
        int get(int a, int b, int fresh) {
            long key = a < b ? ((long) a << 32) | b : ((long) b << 32) | a;
            int slot = (int) (mix(key) & mask);
            while (keys[slot] != -1) {
                if (keys[slot] == key) return values[slot];
                slot = (slot + 1) & mask;
            }
            keys[slot] = key;
            values[slot] = fresh;
            return fresh;
        }

        private static long mix(long key) {
            key *= 0x9E3779B97F4A7C15L;
            return key ^ (key >>> 29);
        }
    }
}
