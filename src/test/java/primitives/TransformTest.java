package primitives;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class TransformTest {
    private static final double EPS = 1e-12;

    @Test
    void composesInOrder() {
        // scale first, then rotate a quarter turn about z, then translate
        Transform t = Transform.scale(2).then(Transform.rotateZ(90)).then(Transform.translate(10, 0, 0));
        assertEquals(new Point(10, 2, 0), t.apply(new Point(1, 0, 0)));
        assertEquals(new Point(8, 0, 6), t.apply(new Point(0, 1, 3)));
    }

    @Test
    void quarterTurnsAreExact() {
        for (int quarter = -8; quarter <= 8; quarter++) {
            double[] m = Transform.rotateX(90 * quarter).toMatrix();
            for (double v : m) assertTrue(v == 0 || v == 1 || v == -1, "entry " + v + " of " + 90 * quarter);
        }
    }

    @Test
    void inverseUndoesTheMap() {
        Random random = new Random(0x7AB5);
        for (int i = 0; i < 200; i++) {
            Transform t = Transform.scale(0.5 + random.nextDouble(), 0.5 + random.nextDouble(), -2)
                    .then(Transform.rotate(
                            new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()),
                            360 * random.nextDouble()))
                    .then(Transform.translate(100 * random.nextGaussian(), 5, -7));
            Point p = new Point(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            Point back = t.inverse().apply(t.apply(p));
            assertEquals(0, back.distance(p), 1e-12 * 200, "round trip of " + p + " through " + t);
        }
    }

    @Test
    void normalsStayPerpendicularUnderStretching() {
        Transform t = Transform.scale(3, 1, 0.5).then(Transform.rotate(new Vector(1, 2, 3), 40));
        Vector tangent = new Vector(1, 0, 0), normal = new Vector(1, 1, 0.3).normalize();
        Vector n2 = t.applyToNormal(normal);
        assertEquals(1, n2.length(), EPS);
        // a tangent perpendicular to the normal stays perpendicular to the transformed normal
        Vector tangentInPlane = tangent.subtract(normal.scale(tangent.dotProduct(normal)));
        assertEquals(0, t.applyToVector(tangentInPlane).dotProduct(n2), 1e-12);
    }

    @Test
    void determinantIsTheVolumeScale() {
        assertEquals(-12, Transform.scale(2, -3, 2).then(Transform.rotateY(33)).determinant(), 1e-12);
    }

    @Test
    void matrixRoundTrips() {
        double[] m = {1, 2, 0, 4, 0, 1, 0, 5, 0, 0, 3, 6};
        assertArrayEquals(m, Transform.ofMatrix(m).toMatrix());
        assertEquals(Transform.ofMatrix(m), Transform.ofMatrix(m.clone()));
    }

    @Test
    void badTransformsAreRefusedWithTheReason() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Transform.scale(1, 0, 1))
                .getMessage()
                .contains("non-zero"));
        assertTrue(assertThrows(
                        IllegalArgumentException.class, () -> Transform.ofMatrix(1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0))
                .getMessage()
                .contains("invertible"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Transform.translate(Double.NaN, 0, 0))
                .getMessage()
                .contains("finite"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Transform.ofMatrix(1, 0, 0))
                .getMessage()
                .contains("12"));
        assertThrows(IllegalArgumentException.class, () -> Transform.rotateZ(Double.POSITIVE_INFINITY));
    }
}
