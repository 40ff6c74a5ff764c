package renderer.sampling;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The first two Sobol dimensions: their first points, and the (0, 2)-net property under any digital shift. */
class Sobol2DTest {

    @Test
    void firstPointsUnshifted() {
        double[][] expected = {{0, 0}, {0.5, 0.5}, {0.25, 0.75}, {0.75, 0.25}, {0.125, 0.625}};
        for (int k = 0; k < expected.length; k++) {
            assertEquals(expected[k][0], Sobol2D.x(k, 0), 0.0, "x of point " + k);
            assertEquals(expected[k][1], Sobol2D.y(k, 0), 0.0, "y of point " + k);
        }
    }

    /**
     * Every aligned block of 2^m points, shifted digitally, puts exactly one point in each elementary rectangle of
     * area 2^-m (2^a columns by 2^(m-a) rows, every a): what makes a progressive pixel's samples well spread.
     */
    @ParameterizedTest(name = "shift {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5})
    void everyAlignedBlockIsANet(int seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int sx = Sobol2D.shift(random.nextDouble()), sy = Sobol2D.shift(random.nextDouble());
        for (int m = 1; m <= 8; m++) {
            int size = 1 << m, start = size * random.nextInt(64);
            for (int a = 0; a <= m; a++) {
                int[] hits = new int[size];
                for (int k = start; k < start + size; k++) {
                    int column = (int) (Sobol2D.x(k, sx) * (1 << a)), row = (int) (Sobol2D.y(k, sy) * (1 << (m - a)));
                    hits[(column << (m - a)) | row]++;
                }
                for (int h : hits) assertEquals(1, h, "m " + m + ", a " + a + ", from point " + start);
            }
        }
    }
}
