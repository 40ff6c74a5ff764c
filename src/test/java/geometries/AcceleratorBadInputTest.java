package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import primitives.Double3;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Bad input to the compiled scene and its BVH: clear errors at build time or documented skipping. */
class AcceleratorBadInputTest {
    private static final Ray DOWN = new Ray(new Point(0.2, 0.1, 5), new Vector(0, 0, -1));

    @Test
    void emptySceneMissesEverythingInBothModes() {
        for (boolean useBvh : new boolean[] {true, false}) {
            Accelerator empty = Accelerator.build(new Geometries(), useBvh);
            HitRecord hit = new HitRecord();
            assertEquals(0, empty.boundedPrimitiveCount());
            assertNull(empty.getBvh());
            assertNull(empty.getBoundingBox());
            assertFalse(empty.intersect(DOWN, 0, Double.POSITIVE_INFINITY, hit));
            assertFalse(empty.occludes(DOWN, 0, Double.POSITIVE_INFINITY, hit));
            assertSame(Double3.ONE, empty.transmittance(DOWN, 0, Double.POSITIVE_INFINITY, hit));
        }
    }

    @Test
    void meshRejectsOutOfRangeAndNegativeIndices() {
        double[] vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        IllegalArgumentException tooLarge =
                assertThrows(IllegalArgumentException.class, () -> new Mesh(vertices, new int[] {0, 1, 3}));
        assertTrue(tooLarge.getMessage().contains("vertex index 3"), tooLarge.getMessage());
        IllegalArgumentException negative =
                assertThrows(IllegalArgumentException.class, () -> new Mesh(vertices, new int[] {0, -1, 2}));
        assertTrue(negative.getMessage().contains("vertex index -1"), negative.getMessage());
    }

    @Test
    void meshRejectsNaNAndInfiniteVertexCoordinates() {
        IllegalArgumentException nan = assertThrows(
                IllegalArgumentException.class,
                () -> new Mesh(new double[] {0, 0, 0, 1, Double.NaN, 0, 0, 1, 0}, new int[] {0, 1, 2}));
        assertTrue(nan.getMessage().contains("vertex 1") && nan.getMessage().contains("NaN"), nan.getMessage());
        assertThrows(
                IllegalArgumentException.class,
                () -> new Mesh(new double[] {0, 0, 0, 1, 0, 0, 0, Double.POSITIVE_INFINITY, 0}, new int[] {0, 1, 2}));
    }

    @Test
    void degenerateMeshTrianglesStayOutOfTheTreeAndBoxesStayFinite() {
        // Triangle 0 is real; 1 repeats a vertex, 2 is collinear, 3 is a single point.
        double[] vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 7, 7, 7};
        int[] indices = {0, 1, 2, 0, 1, 1, 0, 1, 3, 4, 4, 4};
        Mesh mesh = new Mesh(vertices, indices);
        assertFalse(mesh.isDegenerate(0));
        assertTrue(mesh.isDegenerate(1) && mesh.isDegenerate(2) && mesh.isDegenerate(3));

        Accelerator bvh = Accelerator.build(mesh, true);
        assertEquals(1, bvh.boundedPrimitiveCount(), "only the triangle with area is searched");
        BVH tree = bvh.getBvh();
        for (int i = 0; i < tree.nodeCount(); i++) {
            BoundingBox b = tree.node(i).bounds(); // the constructor rejects NaN
            assertTrue(Double.isFinite(b.surfaceArea()), "node " + i + " " + b);
        }
        // The degenerate point at (7, 7, 7) is not part of the scene's bounds.
        assertTrue(bvh.getBoundingBox().maxX < 2, bvh.getBoundingBox().toString());

        HitRecord hit = new HitRecord();
        assertTrue(bvh.intersect(DOWN, 0, Double.POSITIVE_INFINITY, hit));
        assertSame(mesh, hit.geometry);
        assertEquals(0, hit.part);
        Ray alongCollinear = new Ray(new Point(1.5, 0, 5), new Vector(0, 0, -1));
        assertFalse(bvh.intersect(alongCollinear, 0, Double.POSITIVE_INFINITY, hit.reset()));
    }

    @Test
    void meshOfOnlyDegenerateTrianglesIsAnEmptyScene() {
        Mesh flat = new Mesh(new double[] {0, 0, 0, 1, 1, 1, 2, 2, 2}, new int[] {0, 1, 2});
        Accelerator bvh = Accelerator.build(flat, true);
        assertEquals(0, bvh.boundedPrimitiveCount());
        assertFalse(bvh.intersect(new Ray(new Point(1, 1, 5), new Vector(0, 0, -1)), 0, 1e9, new HitRecord()));
    }

    @ParameterizedTest(name = "bins {0}, max leaf size {1}")
    @CsvSource({"1, 4", "257, 4", "16, 0", "16, 65", "-3, -3"})
    void buildSettingsAreValidatedEvenForEmptyAndBruteForceScenes(int bins, int maxLeafSize) {
        Geometries scene = new Geometries(new Sphere(Point.ZERO, 1));
        assertThrows(IllegalArgumentException.class, () -> Accelerator.build(scene, true, bins, maxLeafSize));
        assertThrows(IllegalArgumentException.class, () -> Accelerator.build(scene, false, bins, maxLeafSize));
        assertThrows(
                IllegalArgumentException.class, () -> Accelerator.build(new Geometries(), true, bins, maxLeafSize));
    }

    @Test
    void bvhRejectsNaNPrimitiveBoxes() {
        double[] boxes = {0, 0, 0, 1, 1, 1, 0, Double.NaN, 0, 1, 1, 1};
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> BVH.build(boxes, 16, 4));
        assertTrue(e.getMessage().contains("primitive 1"), e.getMessage());
    }
}
