package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The procedural benchmark meshes: sizes, closedness, orientation and the surface they describe. */
class MeshesTest {
    @ParameterizedTest(name = "n = {0}")
    @CsvSource({"1, 2", "3, 18", "224, 100352"})
    void heightfieldHasTwoTrianglesPerQuad(int n, int triangles) {
        Mesh mesh = Meshes.heightfield(n);
        assertEquals(triangles, mesh.triangleCount());
        assertEquals((n + 1) * (n + 1), mesh.vertexCount());
    }

    @Test
    void heightfieldFollowsTheHeightFunctionAndFacesUp() {
        Mesh mesh = Meshes.heightfield(8);
        for (int i = 0; i < mesh.vertexCount(); i++) {
            var p = mesh.vertex(i);
            assertTrue(p.x >= -1 && p.x <= 1 && p.y >= -1 && p.y <= 1, p.toString());
            assertEquals(Meshes.height(p.x, p.y), p.z);
        }
        for (int t = 0; t < mesh.triangleCount(); t++) {
            int[] idx = mesh.indices;
            assertTrue(
                    WatertightTriangle.normal(mesh.vertices, 3 * idx[3 * t], 3 * idx[3 * t + 1], 3 * idx[3 * t + 2]).z
                            > 0,
                    "triangle " + t + " faces +z");
        }
    }

    @ParameterizedTest(name = "level {0}")
    @CsvSource({"0, 20", "1, 80", "4, 5120"})
    void icosphereIsClosedOutwardAndOnTheUnitSphere(int level, int triangles) {
        Mesh mesh = Meshes.icosphere(level);
        assertEquals(triangles, mesh.triangleCount());
        assertEquals(triangles / 2 + 2, mesh.vertexCount(), "Euler: V = F/2 + 2 for a closed genus-0 mesh");
        for (int i = 0; i < mesh.vertexCount(); i++) {
            var p = mesh.vertex(i);
            assertEquals(1, Math.sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1e-12);
        }
        // Closed and consistently oriented: every directed edge appears once and its reverse once.
        Map<Long, Integer> directed = new HashMap<>();
        int[] idx = mesh.indices;
        for (int t = 0; t < idx.length; t += 3) {
            for (int e = 0; e < 3; e++) {
                long key = ((long) idx[t + e] << 32) | idx[t + (e + 1) % 3];
                assertEquals(null, directed.put(key, t / 3), "directed edge used twice");
            }
            int a = 3 * idx[t], b = 3 * idx[t + 1], c = 3 * idx[t + 2];
            var n = WatertightTriangle.normal(mesh.vertices, a, b, c);
            assertTrue(n.x * mesh.vertices[a] + n.y * mesh.vertices[a + 1] + n.z * mesh.vertices[a + 2] > 0);
        }
        for (long key : directed.keySet()) {
            long reverse = (key << 32) | (key >>> 32);
            assertTrue(directed.containsKey(reverse), "edge without a neighbour");
        }
    }

    /**
     * The hit path's allocation-free {@code setNormal} gives {@code normal}'s unit vector bit for bit: over an
     * icosphere, triangles facing along the axes (exact axis normals) and triangles 1e-150 and 1e150 across (normals out of the squares' range).
     */
    @Test
    void setNormalAgreesWithNormalBitForBit() {
        Mesh mesh = Meshes.icosphere(3);
        int[] idx = mesh.indices;
        HitRecord hit = new HitRecord();
        for (int t = 0; t < idx.length; t += 3) {
            assertSameNormal(mesh.vertices, 3 * idx[t], 3 * idx[t + 1], 3 * idx[t + 2], hit);
        }
        for (double s : new double[] {1, 1e-150, 1e150, 3.7}) {
            assertSameNormal(new double[] {0, 0, 0, s, 0, 0, 0, s, 0}, 0, 3, 6, hit);
            assertSameNormal(new double[] {0, 0, 0, 0, 0, s, s, 0, 0}, 0, 3, 6, hit);
            assertSameNormal(new double[] {0, 0, 0, s, 2 * s, 0, -s, 0.5 * s, 3 * s}, 0, 3, 6, hit);
        }
    }

    private static void assertSameNormal(double[] v, int a, int b, int c, HitRecord hit) {
        var n = WatertightTriangle.normal(v, a, b, c);
        assertTrue(WatertightTriangle.setNormal(v, a, b, c, hit));
        String where =
                "triangle at " + a + " of " + java.util.Arrays.toString(v).substring(0, 40);
        assertEquals(n.x, hit.nx, 0, where);
        assertEquals(n.y, hit.ny, 0, where);
        assertEquals(n.z, hit.nz, 0, where);
    }

    @Test
    void icosphereLevelSixHasTheBenchmarkSize() {
        assertEquals(81_920, Meshes.icosphere(6).triangleCount());
    }

    @Test
    void rejectsSizesOutOfRange() {
        assertThrows(IllegalArgumentException.class, () -> Meshes.heightfield(0));
        assertThrows(IllegalArgumentException.class, () -> Meshes.icosphere(-1));
        assertThrows(IllegalArgumentException.class, () -> Meshes.icosphere(11));
        assertFalse(Meshes.icosphere(0).isDegenerate(0));
    }
}
