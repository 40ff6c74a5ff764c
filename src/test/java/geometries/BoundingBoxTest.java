package geometries;

import static geometries.Hits.assertRejected;
import static geometries.Hits.ray;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Unit tests for {@link BoundingBox}, including the NaN and negative-zero cases of the slab test. */
class BoundingBoxTest {
    private final BoundingBox unit = new BoundingBox(0, 0, 0, 1, 1, 1);

    @Test
    void constructionAndBadInput() {
        assertRejected(() -> new BoundingBox(1, 0, 0, 0, 1, 1), "min must not exceed max");
        assertRejected(() -> new BoundingBox(0, 0, Double.NaN, 1, 1, 1), "NaN");
        // BVA: a flat (zero-thickness) box is fine
        new BoundingBox(0, 0, 0, 1, 1, 0);
        assertEquals(unit, BoundingBox.of(new Point(1, 0, 1), new Point(0, 1, 0)));
        assertEquals(
                new BoundingBox(-1, 0, 0, 2, 3, 1),
                BoundingBox.of(new Point(0, 0, 0), new Point(2, 3, 1), new Point(-1, 1, 0.5)));
    }

    @Test
    void measures() {
        BoundingBox b = new BoundingBox(0, 0, 0, 1, 2, 3);
        assertEquals(2 * (2 + 6 + 3), b.surfaceArea());
        assertEquals(new Point(0.5, 1, 1.5), b.center());
        assertEquals(new Point(0, 0, 0), b.getMin());
        assertEquals(new Point(1, 2, 3), b.getMax());
        assertEquals(new BoundingBox(-1, 0, 0, 1, 2, 5), b.union(new BoundingBox(-1, 1, 4, 0, 1, 5)));
        // contains is inclusive
        assertTrue(b.contains(new Point(1, 2, 3)));
        assertTrue(b.contains(new Point(0, 0, 0)));
        assertFalse(b.contains(new Point(1, 2, Math.nextUp(3.0))));
    }

    @Test
    void slabTestPartitions() {
        double inf = Double.POSITIVE_INFINITY;
        // EP: through, missing, starting inside, behind the ray
        assertTrue(unit.intersects(ray(-1, 0.5, 0.5, 1, 0, 0), 0, inf));
        assertTrue(unit.intersects(ray(-1, -1, -1, 1, 1, 1), 0, inf));
        assertFalse(unit.intersects(ray(-1, 2, 0.5, 1, 0, 0), 0, inf));
        assertFalse(unit.intersects(ray(-1, 0.5, 0.5, 1, 1.6, 0), 0, inf));
        assertTrue(unit.intersects(ray(0.5, 0.5, 0.5, -1, 0.3, 0.2), 0, inf));
        assertFalse(unit.intersects(ray(2, 0.5, 0.5, 1, 0, 0), 0, inf));
        // the interval: the box lies at t in [1, 2]
        Ray r = ray(-1, 0.5, 0.5, 1, 0, 0);
        assertFalse(unit.intersects(r, 0, 0.9));
        assertFalse(unit.intersects(r, 2.1, inf));
        assertTrue(unit.intersects(r, 1.5, 1.6));
    }

    @Test
    void raysParallelToSlabsIncludingNegativeZeroAndNaN() {
        double inf = Double.POSITIVE_INFINITY;
        // parallel to x slabs, inside them: infinite reciprocals
        assertTrue(unit.intersects(ray(0.5, -1, 0.5, 0, 1, 0), 0, inf));
        assertTrue(unit.intersects(ray(0.5, -1, 0.5, -0.0, 1, -0.0), 0, inf));
        // parallel, outside the slab
        assertFalse(unit.intersects(ray(2, -1, 0.5, 0, 1, 0), 0, inf));
        assertFalse(unit.intersects(ray(2, -1, 0.5, -0.0, 1, 0), 0, inf));
        assertFalse(unit.intersects(ray(-1, -1, 0.5, -0.0, 1, 0), 0, inf));
        // exactly in a slab's plane (0 * infinity = NaN): a face-grazing ray must not be culled
        assertTrue(unit.intersects(ray(0, -1, 0.5, 0, 1, 0), 0, inf));
        assertTrue(unit.intersects(ray(1, -1, 0.5, -0.0, 1, 0), 0, inf));
        assertTrue(unit.intersects(ray(-1, 0, 1, 1, 0, -0.0), 0, inf));
        // along an edge of the box
        assertTrue(unit.intersects(ray(-1, 0, 0, 1, 0, 0), 0, inf));
        // a flat box (a quad's bounds) hit head-on
        assertTrue(new BoundingBox(0, 0, 0, 1, 1, 0).intersects(ray(0.5, 0.5, 1, 0, 0, -1), 0, inf));
    }

    static Stream<Arguments> seeds() {
        return LongStream.range(0, 10).mapToObj(i -> Arguments.of(0xB0C5L + 41L * i));
    }

    /**
     * Random boxes and rays (a quarter with a zero or negative-zero component), checked against an independent
     * reference that handles parallel axes explicitly instead of through infinities. The robust test must agree
     * wherever the reference decides by a margin.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void agreesWithAReferenceSlabTest(long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 2000; i++) {
            double x0 = random.nextGaussian() * 5, y0 = random.nextGaussian() * 5, z0 = random.nextGaussian() * 5;
            BoundingBox box = new BoundingBox(
                    x0,
                    y0,
                    z0,
                    x0 + random.nextDouble() * 4,
                    y0 + random.nextDouble() * 4,
                    z0 + random.nextDouble() * 4);
            Point o = new Point(random.nextGaussian() * 8, random.nextGaussian() * 8, random.nextGaussian() * 8);
            double[] d = {random.nextGaussian(), random.nextGaussian(), random.nextGaussian()};
            if (random.nextInt(4) == 0) d[random.nextInt(3)] = random.nextBoolean() ? 0.0 : -0.0;
            Ray ray = new Ray(o, new Vector(d[0], d[1], d[2]));
            double margin = referenceMargin(box, ray);
            if (Math.abs(margin) < 1e-9) continue;
            assertEquals(
                    margin > 0,
                    box.intersects(ray, 0, Double.POSITIVE_INFINITY),
                    "seed " + seed + " case " + i + ": " + box + " " + ray + " margin " + margin);
        }
    }

    /** Length of the overlap of the ray's [0, inf) with the box's slabs (negative: the gap). */
    private static double referenceMargin(BoundingBox b, Ray r) {
        double lo = 0, hi = Double.POSITIVE_INFINITY;
        double[] o = {r.ox(), r.oy(), r.oz()}, d = {r.dx(), r.dy(), r.dz()};
        double[] min = {b.minX, b.minY, b.minZ}, max = {b.maxX, b.maxY, b.maxZ};
        for (int a = 0; a < 3; a++) {
            if (d[a] == 0) {
                // parallel: inside the slab or not, by how much
                double gap = Math.max(min[a] - o[a], o[a] - max[a]);
                if (gap > 0) return -gap;
                continue;
            }
            double t0 = (min[a] - o[a]) / d[a], t1 = (max[a] - o[a]) / d[a];
            lo = Math.max(lo, Math.min(t0, t1));
            hi = Math.min(hi, Math.max(t0, t1));
        }
        return hi - lo;
    }
}
