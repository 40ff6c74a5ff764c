package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Color}: linear, unclamped arithmetic. */
class ColorTest {
    private final Color c = new Color(100, 50, 10);

    @Test
    void channels() {
        assertEquals(100, c.getR());
        assertEquals(50, c.getG());
        assertEquals(10, c.getB());
        assertEquals(new Double3(100, 50, 10), c.toDouble3());
        assertEquals(new Color(255, 128, 0), new Color(new java.awt.Color(255, 128, 0)));
    }

    @Test
    void addIsNotClamped() {
        // values beyond 255 survive until the image is written
        assertEquals(new Color(300, 100, 20), c.add(new Color(200, 50, 10)));
        assertEquals(new Color(120, 70, 30), c.add(new Color(10, 10, 10), new Color(10, 10, 10)));
        assertEquals(c, c.add());
        assertEquals(c, c.add(Color.BLACK));
    }

    @Test
    void scaleAndReduce() {
        assertEquals(new Color(200, 100, 20), c.scale(2));
        assertEquals(new Color(50, 25, 5), c.reduce(2));
        assertEquals(new Color(10, 25, 10), c.scale(new Double3(0.1, 0.5, 1)));
        // BVA: scaling by zero is black
        assertTrue(c.scale(0).isBlack());
        assertTrue(c.scale(Double3.ZERO).isBlack());
    }

    @Test
    void predicatesAndEquality() {
        assertTrue(Color.BLACK.isBlack());
        assertFalse(new Color(0, 0, 1e-9).isBlack());
        assertTrue(c.isFinite());
        assertFalse(new Color(Double.POSITIVE_INFINITY, 0, 0).isFinite());
        assertFalse(new Color(0, Double.NaN, 0).isFinite());
        assertEquals(new Color(100, 50, 10), c);
        assertEquals(new Color(100, 50, 10).hashCode(), c.hashCode());
        assertNotEquals(new Color(100, 50, 11), c);
    }

    @Test
    void negativeChannelsAreKeptLinear() {
        // Linear arithmetic: no silent clamping to zero either (the writer clamps)
        Color negative = new Color(-10, 0, 5);
        assertEquals(-10, negative.getR());
        assertEquals(new Color(90, 50, 15), c.add(negative));
    }
}
