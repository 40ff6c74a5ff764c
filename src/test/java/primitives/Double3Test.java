package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Double3}. */
class Double3Test {
    private final Double3 a = new Double3(1, 2, 3);
    private final Double3 b = new Double3(0.5, -1, 4);

    @Test
    void arithmetic() {
        assertEquals(new Double3(1.5, 1, 7), a.add(b));
        assertEquals(new Double3(0.5, 3, -1), a.subtract(b));
        assertEquals(new Double3(2, 4, 6), a.scale(2));
        assertEquals(new Double3(0.5, -2, 12), a.product(b));
        assertEquals(new Double3(0.5, 1, 1.5), a.reduce(2));
        assertEquals(new Double3(7, 7, 7), new Double3(7));
        // BVA: the neutral elements
        assertEquals(a, a.add(Double3.ZERO));
        assertEquals(a, a.product(Double3.ONE));
        assertEquals(Double3.ZERO, a.scale(0));
    }

    @Test
    void predicates() {
        assertTrue(Double3.ZERO.isZero());
        assertFalse(new Double3(0, 0, 1e-300).isZero());
        assertTrue(new Double3(-0.0, 0, 0).isZero());
        assertEquals(3, a.max());
        assertEquals(4, b.max());
        // lowerThan is strict and needs all three components below
        assertTrue(a.lowerThan(3.0001));
        assertFalse(a.lowerThan(3));
        assertFalse(new Double3(0, 0, 5).lowerThan(1));
    }

    @Test
    void requireInRange() {
        // EP: inside; BVA: exactly on both ends
        assertSame(a, a.requireInRange(0, 3, "k"));
        assertSame(a, a.requireInRange(1, 3, "k"));
        // out of range and NaN: the message names the parameter and the value
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> b.requireInRange(0, 10, "kD"));
        assertTrue(e.getMessage().contains("kD") && e.getMessage().contains("-1.0"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Double3(Double.NaN).requireInRange(0, 1, "x"));
        assertThrows(IllegalArgumentException.class, () -> a.requireInRange(0, 2.9999, "x"));
    }

    @Test
    void equality() {
        assertEquals(new Double3(1, 2, 3), a);
        assertEquals(new Double3(1, 2, 3).hashCode(), a.hashCode());
        assertNotEquals(b, a);
        assertNotEquals(new Double3(1, 2, 3.1), a);
        assertEquals("(1.0,2.0,3.0)", a.toString());
    }
}
