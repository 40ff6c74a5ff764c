package renderer.sampling;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** The blackboard's sample offsets: exact counts, inside the target, even coverage, determinism. */
class SuperSamplingBlackboardTest {

    static Stream<Arguments> everyPatternShapeAndCount() {
        List<Arguments> cases = new ArrayList<>();
        for (SamplingPattern pattern : SamplingPattern.values()) {
            for (TargetShape shape : TargetShape.values()) {
                for (int count : new int[] {1, 2, 3, 5, 7, 10, 16, 17, 81, 100, 257}) {
                    cases.add(Arguments.of(pattern, shape, count));
                }
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0} {1} {2}")
    @MethodSource("everyPatternShapeAndCount")
    void honoursTheCountExactlyAndStaysInsideTheTarget(SamplingPattern pattern, TargetShape shape, int count) {
        double[] offsets = SuperSamplingBlackboard.getSampleOffsets(
                new SamplingConfig(count, shape, pattern), new SampleStream(42));
        assertEquals(2 * count, offsets.length, "one x, y pair per requested sample");
        for (int i = 0; i < count; i++) {
            double x = offsets[2 * i], y = offsets[2 * i + 1];
            if (shape == TargetShape.RECTANGLE) {
                assertTrue(Math.abs(x) <= 0.5 && Math.abs(y) <= 0.5, "sample " + i + " (" + x + ", " + y + ")");
            } else {
                assertTrue(x * x + y * y <= 0.25 + 1e-12, "sample " + i + " (" + x + ", " + y + ") outside the disk");
            }
        }
        if (count > 1 && pattern != SamplingPattern.RANDOM) {
            // Distinct positions: no two samples of a stratified or low-discrepancy set coincide.
            for (int i = 0; i < count; i++) {
                for (int j = i + 1; j < count; j++) {
                    assertFalse(
                            offsets[2 * i] == offsets[2 * j] && offsets[2 * i + 1] == offsets[2 * j + 1],
                            "samples " + i + " and " + j + " coincide");
                }
            }
        }
    }

    @Test
    void oneSampleIsTheCentre() {
        for (SamplingPattern pattern : SamplingPattern.values()) {
            for (TargetShape shape : TargetShape.values()) {
                assertArrayEquals(
                        new double[] {0, 0},
                        SuperSamplingBlackboard.getSampleOffsets(
                                new SamplingConfig(1, shape, pattern), new SampleStream(7)));
            }
        }
    }

    @Test
    void fiveGridSamplesAreFiveNotFour() {
        double[] offsets = SuperSamplingBlackboard.getSampleOffsets(
                new SamplingConfig(5, TargetShape.RECTANGLE, SamplingPattern.GRID), new SampleStream(0));
        assertEquals(10, offsets.length);
        // Two rows (round(sqrt 5) = 2) of 3 and 2 cell centres.
        assertArrayEquals(
                new double[] {-1 / 3.0, -0.25, 0, -0.25, 1 / 3.0, -0.25, -0.25, 0.25, 0.25, 0.25}, offsets, 1e-15);
    }

    @Test
    void gridIsTheLatticeOfCellCentres() {
        double[] offsets = SuperSamplingBlackboard.getSampleOffsets(
                new SamplingConfig(9, TargetShape.RECTANGLE, SamplingPattern.GRID), new SampleStream(0));
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                int i = 3 * r + c;
                assertEquals((c + 0.5) / 3 - 0.5, offsets[2 * i], 1e-15);
                assertEquals((r + 0.5) / 3 - 0.5, offsets[2 * i + 1], 1e-15);
            }
        }
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void jitteredPutsExactlyOneSampleInEachCell(long seed) {
        double[] offsets = SuperSamplingBlackboard.getSampleOffsets(
                new SamplingConfig(64, TargetShape.RECTANGLE, SamplingPattern.JITTERED), new SampleStream(seed));
        int[] cells = new int[64];
        for (int i = 0; i < 64; i++) {
            int cx = (int) Math.floor((offsets[2 * i] + 0.5) * 8);
            int cy = (int) Math.floor((offsets[2 * i + 1] + 0.5) * 8);
            cells[cy * 8 + cx]++;
        }
        for (int cell = 0; cell < 64; cell++) assertEquals(1, cells[cell], "cell " + cell + " (seed " + seed + ")");
    }

    static Stream<Long> seeds() {
        return Stream.of(1L, 2L, 3L, 0xDEADBEEFL, -5L);
    }

    @Test
    void sameStreamSameOffsetsDifferentStreamDifferentOffsets() {
        SamplingConfig config = new SamplingConfig(16, TargetShape.CIRCLE, SamplingPattern.JITTERED);
        double[] a = SuperSamplingBlackboard.getSampleOffsets(config, new SampleStream(99));
        double[] b = SuperSamplingBlackboard.getSampleOffsets(config, new SampleStream(99));
        double[] c = SuperSamplingBlackboard.getSampleOffsets(config, new SampleStream(100));
        assertArrayEquals(a, b);
        assertFalse(java.util.Arrays.equals(a, c));
    }

    /**
     * The low-discrepancy pattern integrates a smooth function better than independent random points: over many
     * seeds, the mean squared error of the sample mean of f(x, y) = sin(3x) cos(2y) + x y is smaller.
     */
    @Test
    void haltonBeatsRandomAtEqualSampleCount() {
        int count = 64, trials = 200;
        double exact = integrate();
        double haltonError = 0, randomError = 0;
        for (int t = 0; t < trials; t++) {
            haltonError += squaredError(SamplingPattern.HALTON, count, t, exact);
            randomError += squaredError(SamplingPattern.RANDOM, count, t, exact);
        }
        assertTrue(
                haltonError * 4 < randomError,
                "Halton MSE " + haltonError / trials + " should be far below random MSE " + randomError / trials);
    }

    private static double squaredError(SamplingPattern pattern, int count, long seed, double exact) {
        double[] o = SuperSamplingBlackboard.getSampleOffsets(
                new SamplingConfig(count, TargetShape.RECTANGLE, pattern), new SampleStream(seed));
        double sum = 0;
        for (int i = 0; i < count; i++) sum += f(o[2 * i], o[2 * i + 1]);
        double e = sum / count - exact;
        return e * e;
    }

    private static double f(double x, double y) {
        return Math.sin(3 * x) * Math.cos(2 * y) + x * y + x * x;
    }

    /** Midpoint rule on a fine grid: independent of the code under test. */
    private static double integrate() {
        int n = 2000;
        double sum = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) sum += f((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5);
        }
        return sum / ((double) n * n);
    }

    /**
     * The mapping chooses its case by masks instead of branches: it must give Shirley and Chiu's concentric map as the
     * textbook writes it (here with Math's sine and cosine), on both sides of the diagonals, on the axes and at the
     * centre.
     */
    @Test
    void concentricDiskIsTheTextbookMapping() {
        java.util.SplittableRandom random = new java.util.SplittableRandom(20261126);
        double[] out = new double[2];
        for (int i = 0; i < 200_000; i++) {
            double u = random.nextDouble(), v = random.nextDouble();
            if (i % 5 == 0) v = i % 10 == 0 ? u : 1 - u; // on a diagonal, |a| = |b|
            if (i % 7 == 0) u = 0.5; // a = 0
            if (i % 11 == 0) v = 0.5; // b = 0
            SuperSamplingBlackboard.concentricDisk(u, v, out, 0);
            double a = 2 * u - 1, b = 2 * v - 1, x = 0, y = 0;
            if (Math.abs(a) > Math.abs(b)) {
                x = 0.5 * a * Math.cos(Math.PI / 4 * (b / a));
                y = 0.5 * a * Math.sin(Math.PI / 4 * (b / a));
            } else if (b != 0) {
                x = 0.5 * b * Math.sin(Math.PI / 4 * (a / b));
                y = 0.5 * b * Math.cos(Math.PI / 4 * (a / b));
            }
            String at = "(" + u + ", " + v + ")";
            assertEquals(x, out[0], 0x1p-52, "x at " + at);
            assertEquals(y, out[1], 0x1p-52, "y at " + at);
        }
    }

    /**
     * A shifted Halton point wraps into [0, 1) by subtracting its floor, without a branch (which side a point falls on
     * is a coin toss): it must be the textbook's {@code x >= 1 ? x - 1 : x} bit for bit, including shifts that land a
     * point exactly on 1 and shifts just below 1.
     */
    @Test
    void continuedHaltonPointsWrapAsTheTextbookSays() {
        java.util.SplittableRandom random = new java.util.SplittableRandom(20261126);
        double[] out = new double[2 * 64];
        for (int trial = 0; trial < 2_000; trial++) {
            double rx = random.nextDouble(), ry = random.nextDouble();
            if (trial % 4 == 1) rx = ry = 0.5; // point 1 is (1/2, 1/3): x lands on exactly 1
            if (trial % 4 == 2) rx = ry = Math.nextDown(1.0);
            if (trial % 4 == 3) rx = ry = 0;
            long first = trial % 4 == 1 ? 0 : trial % 2 == 0 ? random.nextInt(1 << 20) : random.nextInt((1 << 14) - 64);
            SuperSamplingBlackboard.haltonContinued(64, first, TargetShape.RECTANGLE, rx, ry, out);
            for (int i = 0; i < 64; i++) {
                int index = (int) first + i + 1;
                double x = SuperSamplingBlackboard.radicalInverse(2, index) + rx;
                double y = SuperSamplingBlackboard.radicalInverse(3, index) + ry;
                x = x >= 1 ? x - 1 : x;
                y = y >= 1 ? y - 1 : y;
                String at = "point " + index + " shifted by (" + rx + ", " + ry + ")";
                assertEquals(x - 0.5, out[2 * i], 0, "x of " + at);
                // (Beyond the first 16,384 points the beams' base-3 coordinate sums its digits in another order than
                // radicalInverse does, a last-bit difference that has nothing to do with the wrapping.)
                if (index < 1 << 14) assertEquals(y - 0.5, out[2 * i + 1], 0, "y of " + at);
            }
        }
    }

    @Test
    void diskSamplesCoverTheDiskEvenly() {
        // Equal-area rings: the inner disk of radius 0.5/sqrt(2) holds half the area, so about half the samples.
        double[] o = SuperSamplingBlackboard.getSampleOffsets(
                new SamplingConfig(400, TargetShape.CIRCLE, SamplingPattern.GRID), new SampleStream(0));
        int inner = 0;
        for (int i = 0; i < 400; i++) {
            if (o[2 * i] * o[2 * i] + o[2 * i + 1] * o[2 * i + 1] < 0.125) inner++;
        }
        assertEquals(200, inner, 12, "samples in the inner half-area disk");
    }

    @Test
    void rejectsBadCountsAndBuffers() {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class,
                () -> new SamplingConfig(0, TargetShape.RECTANGLE, SamplingPattern.GRID));
        assertTrue(e.getMessage().contains("sampleCount") && e.getMessage().contains("0"), e.getMessage());
        assertThrows(
                IllegalArgumentException.class,
                () -> SuperSamplingBlackboard.getSampleOffsets(
                        4, TargetShape.RECTANGLE, SamplingPattern.GRID, new SampleStream(0), new double[6]));
    }

    static Stream<Arguments> probeCountsAndSeeds() {
        List<Arguments> cases = new ArrayList<>();
        for (int count : new int[] {2, 3, 5, 9, 17, 33, 34, 100}) {
            for (long seed = 1; seed <= 5; seed++) cases.add(Arguments.of(count, seed));
        }
        return cases.stream();
    }

    /**
     * The probe ring (the centre, then {@code count - 1} rim points turned by one random angle) against the textbook's
     * {@code 0.5 (cos, sin)(rotation + 2 pi (i - 1) / (count - 1))}, within 2e-15, what rounding the textbook's own
     * angle (up to 4 pi, whose ulp is 1.8e-15) allows: the rim's points are turned from a table of the unrotated ring,
     * not computed one by one (above 32 rim points they still are).
     */
    @ParameterizedTest(name = "{0} probes, seed {1}")
    @MethodSource("probeCountsAndSeeds")
    void probeRingIsTheTextbooksRotatedRing(int count, long seed) {
        double[] out = new double[2 * count];
        SuperSamplingBlackboard.getProbeOffsets(count, new SampleStream(seed), out);
        double rotation = 2 * Math.PI * new SampleStream(seed).nextDouble();
        assertEquals(0.0, out[0]);
        assertEquals(0.0, out[1]);
        for (int i = 1; i < count; i++) {
            double angle = rotation + 2 * Math.PI * (i - 1) / (count - 1);
            assertEquals(0.5 * Math.cos(angle), out[2 * i], 2e-15, "x of probe " + i);
            assertEquals(0.5 * Math.sin(angle), out[2 * i + 1], 2e-15, "y of probe " + i);
        }
    }
}
