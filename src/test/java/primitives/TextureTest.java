package primitives;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;

/** Bilinear lookup, texel centres, wrap modes and validation of {@link Texture}. */
class TextureTest {
    /** 2 x 2: top row red, green; bottom row blue, white (rows from the top of the image). */
    private static final float[] TWO_BY_TWO = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};

    private static double[] at(Texture t, double u, double v) {
        double[] out = new double[3];
        t.lookup(u, v, out);
        return out;
    }

    @ParameterizedTest
    @EnumSource(Texture.Wrap.class)
    void texelCentresGiveTheTexelExactly(Texture.Wrap wrap) {
        Texture t = new Texture(2, 2, TWO_BY_TWO, wrap);
        assertArrayEquals(new double[] {1, 0, 0}, at(t, 0.25, 0.75)); // top left
        assertArrayEquals(new double[] {0, 1, 0}, at(t, 0.75, 0.75)); // top right
        assertArrayEquals(new double[] {0, 0, 1}, at(t, 0.25, 0.25)); // bottom left
        assertArrayEquals(new double[] {1, 1, 1}, at(t, 0.75, 0.25)); // bottom right
    }

    @Test
    void bilinearBlendsTheFourNearestTexels() {
        Texture t = new Texture(2, 2, TWO_BY_TWO, Texture.Wrap.CLAMP);
        // The image centre is equally far from all four texel centres.
        assertArrayEquals(new double[] {0.5, 0.5, 0.5}, at(t, 0.5, 0.5), 1e-15);
        // Halfway between the top texels.
        assertArrayEquals(new double[] {0.5, 0.5, 0}, at(t, 0.5, 0.75), 1e-15);
        // A quarter of the way from top-left toward top-right.
        assertArrayEquals(new double[] {0.75, 0.25, 0}, at(t, 0.375, 0.75), 1e-15);
    }

    @Test
    void clampExtendsTheEdgeTexels() {
        Texture t = new Texture(2, 2, TWO_BY_TWO, Texture.Wrap.CLAMP);
        assertArrayEquals(new double[] {1, 0, 0}, at(t, -3, 7));
        assertArrayEquals(new double[] {1, 1, 1}, at(t, 5, -2));
        assertArrayEquals(new double[] {1, 0, 0}, at(t, 0, 1)); // the corner is the texel's outer edge
    }

    @Test
    void repeatTilesAndBlendsAcrossTheSeam() {
        Texture t = new Texture(2, 2, TWO_BY_TWO, Texture.Wrap.REPEAT);
        assertArrayEquals(at(t, 0.25, 0.75), at(t, 3.25, -1.25));
        // At u = 0 the left and right columns meet: half of each.
        assertArrayEquals(new double[] {0.5, 0.5, 0}, at(t, 0, 0.75), 1e-15);
    }

    @Test
    void mirrorReflectsEveryOtherTile() {
        Texture t = new Texture(2, 1, new float[] {0, 0, 0, 1, 1, 1}, Texture.Wrap.MIRROR);
        assertArrayEquals(new double[] {1, 1, 1}, at(t, 0.75, 0.5));
        assertArrayEquals(new double[] {1, 1, 1}, at(t, 1.25, 0.5)); // mirrored: the right texel again
        assertArrayEquals(new double[] {0, 0, 0}, at(t, 1.75, 0.5));
        assertArrayEquals(new double[] {0, 0, 0}, at(t, -0.25, 0.5));
        assertArrayEquals(new double[] {1, 1, 1}, at(t, 1.0, 0.5)); // no seam at the mirror line
    }

    static Stream<double[]> coordinates() {
        Random random = new Random(17);
        return Stream.generate(() -> new double[] {
                    (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(12)),
                    (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(12))
                })
                .limit(200);
    }

    /** Any coordinate gives a convex blend of texels: within the range of the texel values. */
    @ParameterizedTest
    @MethodSource("coordinates")
    void anyCoordinateGivesABlendOfTexels(double[] uv) {
        for (Texture.Wrap wrap : Texture.Wrap.values()) {
            Texture t = new Texture(
                    3, 2, new float[] {0, 1, 0.5f, 1, 0, 0.25f, 0, 0, 1, 1, 1, 0, 0.5f, 0.5f, 0.5f, 0, 1, 1}, wrap);
            for (double value : at(t, uv[0], uv[1])) assertTrue(value >= 0 && value <= 1, wrap + " " + value);
        }
    }

    @Test
    void nonFiniteCoordinatesCountAsZero() {
        Texture t = new Texture(2, 2, TWO_BY_TWO, Texture.Wrap.REPEAT);
        assertArrayEquals(at(t, 0, 0), at(t, Double.NaN, Double.POSITIVE_INFINITY));
    }

    @Test
    void badTexturesAreRejectedWithTheReason() {
        Texture.Wrap r = Texture.Wrap.REPEAT;
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Texture(0, 2, new float[0], r))
                .getMessage()
                .contains("0 x 2"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Texture(2, 2, new float[11], r))
                .getMessage()
                .contains("needs 12 values"));
        float[] negative = TWO_BY_TWO.clone();
        negative[4] = -1;
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Texture(2, 2, negative, r))
                .getMessage()
                .contains("texture value 4"));
        float[] nan = TWO_BY_TWO.clone();
        nan[0] = Float.NaN;
        assertThrows(IllegalArgumentException.class, () -> new Texture(2, 2, nan, r));
        assertThrows(IllegalArgumentException.class, () -> new Texture(Texture.MAX_SIDE + 1, 1, new float[0], r));
    }

    @Test
    void withWrapSharesTheTexels() {
        Texture t = new Texture(2, 2, TWO_BY_TWO, Texture.Wrap.REPEAT);
        Texture clamped = t.withWrap(Texture.Wrap.CLAMP);
        assertEquals(Texture.Wrap.CLAMP, clamped.getWrap());
        assertArrayEquals(new double[] {1, 0, 0}, at(clamped, -1, 2));
        assertEquals(t, t.withWrap(Texture.Wrap.REPEAT));
    }
}
