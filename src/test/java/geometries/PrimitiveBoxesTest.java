package geometries;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Point;

/**
 * The primitive boxes the BVH is built from ({@link PrimitiveCollector#boxes}) are floats rounded to the nearest, after
 * a pad: each must still hold its triangle with room to spare, 1e-14 of the box's largest magnitude at least (what
 * the double boxes before them kept for the kernels' rounding), at every scale from float's subnormals to beyond its
 * range.
 */
class PrimitiveBoxesTest {

    static Stream<Double> scales() {
        return Stream.of(1e-44, 1e-30, 1e-3, 1.0, 3e6, 1e20, 1e38, 1e150);
    }

    @ParameterizedTest(name = "scale {0}")
    @MethodSource("scales")
    void everyBoxHoldsItsTriangleWithRoomToSpare(double scale) {
        Random random = new Random(Double.hashCode(scale));
        PrimitiveCollector collector = new PrimitiveCollector();
        int n = 2000;
        for (int i = 0; i < n; i++) {
            Point[] v = new Point[3];
            // Some triangles far from the origin relative to their size, some straddling it.
            double offset = random.nextBoolean() ? scale * (random.nextDouble() - 0.5) * 1e4 : 0;
            for (int k = 0; k < 3; k++) {
                v[k] = new Point(
                        offset + scale * random.nextGaussian(),
                        offset + scale * random.nextGaussian(),
                        scale * random.nextGaussian());
            }
            collector.collect(new Triangle(v[0], v[1], v[2]));
        }
        float[] boxes = collector.boxes();
        double[] triangle = new double[9];
        for (int p = 0; p < n; p++) {
            collector.copyTriangle(p, triangle, 0);
            for (int a = 0; a < 3; a++) {
                double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < 3; k++) {
                    double c = triangle[3 * k + a];
                    lo = Math.min(lo, c);
                    hi = Math.max(hi, c);
                }
                double room = 1e-14 * Math.max(Math.abs(lo), Math.abs(hi));
                float min = boxes[BVH.BOX_STRIDE * p + a], max = boxes[BVH.BOX_STRIDE * p + BVH.BOX_MAX + a];
                // Beyond float's range the far side is infinite and the near side float's largest value.
                assertTrue(min < lo - room, p + " axis " + a + ": " + min + " against " + lo);
                assertTrue(max > hi + room, p + " axis " + a + ": " + max + " against " + hi);
            }
        }
    }
}
