package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The planning's 3 x 3 filters against their definition, bit for bit: the largest (raised around each value that is
 * not 0) and the mean (skipped where the largest is 0), on images mostly of zeros (of both signs) as a converging
 * render's variances are and on one without zeros, at the edges and corners, on images one pixel wide or high, and
 * with a NaN, which both pass on; and the mean of each pixel's neighbours without itself.
 */
class NeighbourhoodsTest {
    static Stream<Arguments> images() {
        return Stream.of(
                Arguments.of(1, 1, 11L),
                Arguments.of(1, 7, 12L),
                Arguments.of(9, 1, 13L),
                Arguments.of(2, 2, 14L),
                Arguments.of(17, 13, 15L),
                Arguments.of(64, 40, 16L),
                Arguments.of(33, 21, 17L));
    }

    @ParameterizedTest(name = "{0} x {1}")
    @MethodSource("images")
    void filtersMatchTheirDefinition(int nX, int nY, long seed) {
        Random random = new Random(seed);
        double[] values = new double[nX * nY];
        // Mostly zeros, as a converging render's variances are; the last image has no zeros at all.
        boolean dense = seed == 17L;
        for (int p = 0; p < values.length; p++) {
            values[p] = dense || random.nextInt(4) == 0
                    ? random.nextDouble() * Math.pow(10, random.nextInt(9) - 4)
                    : random.nextBoolean() ? 0.0 : -0.0;
        }
        if (values.length > 3) values[values.length / 3] = Double.NaN;
        Neighbourhoods filters = new Neighbourhoods(nX, nY);
        // The filters write every pixel of their output, whatever it held (the arrays are reused pass after pass).
        double[] largest = new double[values.length],
                mean = new double[values.length],
                others = new double[values.length];
        Arrays.fill(largest, 7.5);
        Arrays.fill(mean, Double.NaN);
        Arrays.fill(others, Double.NaN);
        filters.largest(values, largest);
        filters.mean(values, largest, mean);
        filters.meanOfOthers(values, largest, others);
        for (int y = 0; y < nY; y++) {
            for (int x = 0; x < nX; x++) {
                double max = 0, sum = 0, sumOthers = 0;
                int n = 0;
                for (int j = Math.max(0, y - 1); j <= Math.min(nY - 1, y + 1); j++) {
                    for (int i = Math.max(0, x - 1); i <= Math.min(nX - 1, x + 1); i++) {
                        max = Math.max(max, values[j * nX + i]);
                        sum += values[j * nX + i];
                        if (j != y || i != x) sumOthers += values[j * nX + i];
                        n++;
                    }
                }
                String where = "(" + x + ", " + y + ")";
                assertEquals(Double.doubleToLongBits(max), Double.doubleToLongBits(largest[y * nX + x]), where);
                assertEquals(Double.doubleToLongBits(sum / n), Double.doubleToLongBits(mean[y * nX + x]), where);
                // Without the pixel itself: the mean of the others, 0 where all are 0 (as the largest says) or none.
                double expected = max == 0 || n == 1 ? 0 : sumOthers / (n - 1);
                assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(others[y * nX + x]), where);
            }
        }
    }
}
