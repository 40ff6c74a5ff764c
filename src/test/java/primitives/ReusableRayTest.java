package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class ReusableRayTest {
    /** Seeded origins and directions over many magnitudes, including tiny and huge components. */
    static Stream<double[]> rays() {
        Random random = new Random(20261124);
        return Stream.generate(() -> {
                    double scale = Math.pow(10, random.nextInt(40) - 20);
                    double[] r = new double[6];
                    for (int i = 0; i < 6; i++) r[i] = (random.nextDouble() * 2 - 1) * (i < 3 ? 1000 : scale);
                    if (random.nextInt(4) == 0) r[3 + random.nextInt(3)] = 0;
                    return r;
                })
                .filter(r -> r[3] != 0 || r[4] != 0 || r[5] != 0)
                .limit(200);
    }

    @ParameterizedTest
    @MethodSource("rays")
    void holdsExactlyWhatAConstructedRayHolds(double[] r) {
        Ray made = new Ray(new Point(r[0], r[1], r[2]), new Vector(r[3], r[4], r[5]));
        // Reused: set somewhere else first, its constants read (a reusable ray derives them on first use), so
        // nothing of the earlier ray may survive.
        ReusableRay reused = new ReusableRay().set(1, 2, 3, -4, 5, -6);
        fields(reused);
        reused.set(r[0], r[1], r[2], r[3], r[4], r[5]);
        assertSameRay(made, reused);
    }

    @ParameterizedTest
    @MethodSource("rays")
    void aMovedCopyHoldsExactlyWhatAConstructedRayHolds(double[] r) {
        Ray made = new Ray(new Point(r[0], r[1], r[2]), new Vector(r[3], r[4], r[5]));
        // Copied from a ray whose constants were not read yet, and from one whose constants were.
        ReusableRay fresh = new ReusableRay().set(7, 8, 9, r[3], r[4], r[5]);
        ReusableRay read = new ReusableRay().set(7, 8, 9, r[3], r[4], r[5]);
        fields(read);
        for (Ray source : new Ray[] {fresh, read}) {
            ReusableRay moved = new ReusableRay().set(1, 2, 3, -4, 5, -6);
            fields(moved);
            assertSameRay(made, moved.setMoved(source, r[0], r[1], r[2]));
        }
        assertSameRay(new Ray(new Point(7, 8, 9), new Vector(r[3], r[4], r[5])), fresh);
    }

    private static void assertSameRay(Ray expected, Ray actual) {
        assertEquals(expected, actual);
        double[] a = fields(expected), b = fields(actual);
        for (int i = 0; i < a.length; i++)
            assertEquals(Double.doubleToRawLongBits(a[i]), Double.doubleToRawLongBits(b[i]));
        assertEquals(expected.getHead(), actual.getHead());
        assertEquals(expected.getDirection(), actual.getDirection());
    }

    private static double[] fields(Ray r) {
        return new double[] {
            r.ox(),
            r.oy(),
            r.oz(),
            r.dx(),
            r.dy(),
            r.dz(),
            r.invDx(),
            r.invDy(),
            r.invDz(),
            r.kx(),
            r.ky(),
            r.kz(),
            r.shearX(),
            r.shearY(),
            r.shearZ()
        };
    }

    @Test
    void headAndDirectionFollowTheLastSet() {
        ReusableRay ray = new ReusableRay().set(1, 2, 3, 0, 0, 2);
        assertEquals(new Point(1, 2, 3), ray.getHead());
        ray.set(new Point(4, 5, 6), new Vector(3, 0, 0));
        assertEquals(new Point(4, 5, 6), ray.getHead());
        assertEquals(Vector.AXIS_X, ray.getDirection());
    }

    @Test
    void rejectsWhatARayCannotBe() {
        ReusableRay ray = new ReusableRay();
        assertThrows(IllegalArgumentException.class, () -> ray.set(0, 0, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> ray.set(Double.NaN, 0, 0, 1, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> ray.set(0, 0, 0, Double.POSITIVE_INFINITY, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> ray.set(0, 0, 0, Double.NaN, 1, 0));
    }
}
