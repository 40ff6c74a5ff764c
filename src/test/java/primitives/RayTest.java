package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Ray}. */
class RayTest {
    private static final double DELTA = 1e-12;

    @Test
    void directionIsNormalized() {
        Ray ray = new Ray(new Point(1, 2, 3), new Vector(0, 3, 4));
        assertEquals(0, ray.getDirection().x);
        assertEquals(0.6, ray.getDirection().y, 1e-15);
        assertEquals(0.8, ray.getDirection().z, 1e-15);
        assertEquals(new Point(1, 2, 3), ray.getHead());
        // the unpacked fields agree with the objects
        assertEquals(1, ray.ox());
        assertEquals(ray.getDirection().y, ray.dy());
        assertEquals(1 / 0.8, ray.invDz(), DELTA);
    }

    @Test
    void getPoint() {
        Ray ray = new Ray(new Point(1, 0, 0), new Vector(0, 0, 2));
        // EP: positive and negative distances
        assertEquals(new Point(1, 0, 5), ray.getPoint(5));
        assertEquals(new Point(1, 0, -2), ray.getPoint(-2));
        // BVA: t = 0 is the head itself
        assertSame(ray.getHead(), ray.getPoint(0));
        // the distance is measured in units of length (unit direction)
        Ray diagonal = new Ray(Point.ZERO, new Vector(1, 1, 1));
        assertEquals(3, diagonal.getPoint(3).distance(Point.ZERO), DELTA);
    }

    @Test
    void badInputIsRejected() {
        // null origin / direction: the message names the parameter
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Ray(null, Vector.AXIS_X));
        assertTrue(e.getMessage().contains("origin"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new Ray(Point.ZERO, null));
        assertTrue(e.getMessage().contains("direction"), e.getMessage());
        // NaN/infinite origins and zero directions cannot even be constructed
        assertThrows(IllegalArgumentException.class, () -> new Ray(new Point(Double.NaN, 0, 0), Vector.AXIS_X));
        assertThrows(
                IllegalArgumentException.class,
                () -> new Ray(new Point(0, Double.POSITIVE_INFINITY, 0), Vector.AXIS_X));
        assertThrows(IllegalArgumentException.class, () -> new Ray(Point.ZERO, new Vector(0, 0, 0)));
    }

    @Test
    void tinyAndHugeDirectionsAreNormalized() {
        Ray tiny = new Ray(Point.ZERO, new Vector(1e-300, 0, 0));
        assertEquals(Vector.AXIS_X, tiny.getDirection());
        Ray huge = new Ray(Point.ZERO, new Vector(1e300, 1e300, 0));
        assertEquals(Math.sqrt(0.5), huge.dx(), 1e-15);
        assertEquals(Math.sqrt(0.5), huge.dy(), 1e-15);
    }

    @Test
    void dominantAxisOfTheWatertightTestIsTheLargestComponent() {
        assertEquals(0, new Ray(Point.ZERO, new Vector(-5, 1, 2)).kz());
        assertEquals(1, new Ray(Point.ZERO, new Vector(1, 5, -2)).kz());
        assertEquals(2, new Ray(Point.ZERO, new Vector(1, 2, -5)).kz());
        Ray r = new Ray(Point.ZERO, new Vector(1, 2, -5));
        // kx, ky are the other two axes
        assertEquals(3, r.kx() + r.ky() + r.kz());
        assertNotEquals(r.kx(), r.ky());
    }

    @Test
    void equality() {
        Ray a = new Ray(new Point(1, 2, 3), new Vector(0, 0, 2));
        Ray b = new Ray(new Point(1, 2, 3), new Vector(0, 0, 7));
        assertEquals(a, b);
        assertEquals(a.hashCode(), b.hashCode());
        assertNotEquals(a, new Ray(new Point(1, 2, 3), new Vector(0, 0, -7)));
        assertNotEquals(a, new Ray(new Point(1, 2, 4), new Vector(0, 0, 2)));
    }
}
