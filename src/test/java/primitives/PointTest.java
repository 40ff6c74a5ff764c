package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Unit tests for {@link Point}. */
class PointTest {
    private static final double DELTA = 1e-12;
    private final Point p1 = new Point(1, 2, 3);
    private final Point p2 = new Point(2, 4, 6);

    @Test
    void addMovesThePointByTheVector() {
        // EP: a general vector
        assertEquals(new Point(2, 4, 6), p1.add(new Vector(1, 2, 3)));
        // EP: a vector that brings the point to the origin (the result is a point, so zero is fine)
        assertEquals(Point.ZERO, p1.add(new Vector(-1, -2, -3)));
    }

    @Test
    void subtractGivesTheVectorBetweenPoints() {
        // EP: two different points
        Vector v = p2.subtract(p1);
        assertEquals(new Vector(1, 2, 3), v);
        // The result is a Vector (a direction), not just a point
        assertEquals(Vector.class, v.getClass());
        // BVA: subtracting a point from itself gives the zero vector, which is an error
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> p1.subtract(p1));
        assertTrue(e.getMessage().contains("zero"), e.getMessage());
    }

    @Test
    void distances() {
        // EP: 3-4-5 right triangle in a plane, and a general 3D distance
        Point a = new Point(1, 1, 1);
        assertEquals(25, a.distanceSquared(new Point(4, 5, 1)), DELTA);
        assertEquals(5, a.distance(new Point(4, 5, 1)), DELTA);
        assertEquals(Math.sqrt(14), p1.distance(p2), DELTA);
        assertEquals(14, p1.distanceSquared(p2), DELTA);
        // BVA: distance from a point to itself is zero
        assertEquals(0, p1.distance(p1));
        // Symmetric
        assertEquals(p2.distance(p1), p1.distance(p2));
    }

    @Test
    void accessorsAndConversions() {
        assertEquals(1, p1.getX());
        assertEquals(2, p1.getY());
        assertEquals(3, p1.getZ());
        assertEquals(1, p1.get(0));
        assertEquals(2, p1.get(1));
        assertEquals(3, p1.get(2));
        assertEquals(new Double3(1, 2, 3), p1.toDouble3());
        assertEquals(p1, new Point(new Double3(1, 2, 3)));
    }

    @Test
    void equalityAndHash() {
        assertEquals(new Point(1, 2, 3), p1);
        assertEquals(new Point(1, 2, 3).hashCode(), p1.hashCode());
        assertNotEquals(p2, p1);
        assertNotEquals(new Point(1, 2, 3.0000001), p1);
        // A point and a vector with the same coordinates are different things
        assertNotEquals(new Vector(1, 2, 3), p1);
        assertNotEquals(p1, new Vector(1, 2, 3));
        assertNotEquals(null, p1);
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY})
    void nonFiniteCoordinatesAreRejectedWithTheValue(double bad) {
        for (int axis = 0; axis < 3; axis++) {
            double x = axis == 0 ? bad : 0, y = axis == 1 ? bad : 0, z = axis == 2 ? bad : 0;
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Point(x, y, z));
            assertTrue(e.getMessage().contains("finite"), e.getMessage());
            assertTrue(e.getMessage().contains(String.valueOf(bad)), e.getMessage());
        }
    }

    @Test
    void addThatOverflowsIsRejected() {
        // BVA: the sum of two finite coordinates may overflow to infinity: that must not produce a point
        Point huge = new Point(Double.MAX_VALUE, 0, 0);
        assertThrows(IllegalArgumentException.class, () -> huge.add(new Vector(Double.MAX_VALUE, 0, 0)));
    }
}
