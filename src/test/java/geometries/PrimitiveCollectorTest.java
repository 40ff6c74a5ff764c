package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A mesh's triangles with area reach the collector in order, each with its own vertices and its index in the mesh
 * as its part, also where a large mesh is collected on all cores and some of its triangles have no area.
 */
class PrimitiveCollectorTest {

    @ParameterizedTest(name = "every {0}th triangle degenerate")
    @ValueSource(ints = {0, 97, 2})
    void aMeshsTrianglesWithAreaArriveInOrder(int degenerateEvery) {
        // 80,000 triangles: above the size from which the collector works on all cores.
        Mesh grid = Meshes.heightfield(200);
        int[] indices = grid.indices.clone();
        int n = indices.length / 3;
        for (int i = 0; degenerateEvery > 0 && i < n; i += degenerateEvery) {
            indices[3 * i + 2] = indices[3 * i + 1]; // a repeated vertex: no area
        }
        Mesh mesh = new Mesh(grid.vertices, indices);
        PrimitiveCollector collector = new PrimitiveCollector();
        collector.collect(new Triangle(
                new primitives.Point(0, 0, 9), new primitives.Point(1, 0, 9), new primitives.Point(0, 1, 9)));
        collector.collect(mesh);

        double[] triangle = new double[9];
        collector.copyTriangle(0, triangle, 0);
        assertEquals(9, triangle[2], "the lone triangle's own vertices");
        int k = 1; // after the lone triangle
        for (int i = 0; i < n; i++) {
            if (mesh.isDegenerate(i)) continue;
            collector.copyTriangle(k, triangle, 0);
            assertEquals(i, collector.parts[k], "part of primitive " + k);
            assertEquals(WatertightTriangle.ALL_EDGES_SHARED, collector.shared[k]);
            assertEquals(collector.owners[1], collector.owners[k], "one owner for the mesh");
            for (int corner = 0; corner < 3; corner++) {
                for (int a = 0; a < 3; a++) {
                    assertEquals(
                            mesh.vertices[3 * indices[3 * i + corner] + a],
                            triangle[3 * corner + a],
                            "triangle " + i + " corner " + corner);
                }
            }
            k++;
        }
        assertEquals(k, collector.count, "every triangle with area once, nothing else");
    }
}
