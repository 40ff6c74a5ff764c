package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Per-vertex texture coordinates of {@link Mesh}: validation and interpolation into the hit record. */
class MeshTexCoordsTest {
    /** A unit square in z = 0 with texture coordinates equal to x, y times 2. */
    private static final double[] V = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

    private static final int[] I = {0, 1, 2, 0, 2, 3};
    private static final double[] UV = {0, 0, 2, 0, 2, 2, 0, 2};

    private static HitRecord hitAt(Mesh mesh, double x, double y) {
        Ray ray = new Ray(new Point(x, y, 5), new Vector(0, 0, -1));
        HitRecord hit = new HitRecord();
        assertTrue(mesh.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        mesh.completeHit(ray, hit);
        return hit;
    }

    @Test
    void hitsInterpolateTheTextureCoordinates() {
        Mesh mesh = new Mesh(V, I, null, UV);
        for (double[] p : new double[][] {{0.25, 0.1}, {0.8, 0.3}, {0.2, 0.7}, {0.5, 0.5}}) {
            HitRecord hit = hitAt(mesh, p[0], p[1]);
            assertEquals(2 * p[0], hit.texU, 1e-12);
            assertEquals(2 * p[1], hit.texV, 1e-12);
        }
    }

    @Test
    void meshesWithoutTextureCoordinatesLeaveThemAlone() {
        Mesh mesh = new Mesh(V, I);
        assertNull(mesh.getTexCoords());
        HitRecord hit = new HitRecord();
        hit.texU = 7;
        Ray ray = new Ray(new Point(0.5, 0.2, 5), new Vector(0, 0, -1));
        assertTrue(mesh.intersect(ray, 0, Double.POSITIVE_INFINITY, hit));
        mesh.completeHit(ray, hit);
        assertEquals(7, hit.texU, "the tracer zeroes them before completing a hit");
    }

    @Test
    void transformedKeepsTheCoordinatesAndGettersCopy() {
        Mesh mesh = new Mesh(V, I, null, UV).transformed(3, 1, 1, 1);
        assertArrayEquals(UV, mesh.getTexCoords());
        mesh.getTexCoords()[0] = 99;
        assertEquals(0, mesh.getTexCoords()[0]);
    }

    @Test
    void badTextureCoordinatesAreRejected() {
        IllegalArgumentException e =
                assertThrows(IllegalArgumentException.class, () -> new Mesh(V, I, null, new double[7]));
        assertTrue(e.getMessage().contains("one u, v pair per vertex (8 values), but had 7"), e.getMessage());
        double[] nan = UV.clone();
        nan[3] = Double.NaN;
        e = assertThrows(IllegalArgumentException.class, () -> new Mesh(V, I, null, nan));
        assertTrue(e.getMessage().contains("texture coordinate 1"), e.getMessage());
    }
}
