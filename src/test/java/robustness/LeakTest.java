package robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * No ray from inside a closed mesh escapes, even aimed exactly at vertices and edges, near the origin or 1e6
 * away, unit-sized or scaled up, with the BVH and by brute force. The textbook Moller-Trumbore test on the same
 * rays leaks, which shows the rays really probe the seams.
 */
class LeakTest {
    static Stream<Arguments> placements() {
        List<Arguments> cases = new ArrayList<>();
        for (double offset : new double[] {0, 1e6}) {
            for (double scale : new double[] {1, 1e3}) {
                for (long seed : new long[] {3, 20261122L}) cases.add(Arguments.of(offset, scale, seed));
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "offset {0}, scale {1}, seed {2}")
    @MethodSource("placements")
    void noRayEscapesAClosedIcosphere(double offset, double scale, long seed) {
        LeakProbe.Result bvh = LeakProbe.run(2, scale, offset, 2, seed, true);
        LeakProbe.Result brute = LeakProbe.run(2, scale, offset, 2, seed, false);
        String where = "offset " + offset + ", scale " + scale + " (seed " + seed + ")";
        assertTrue(bvh.rays() > 1900, where);
        assertEquals(0, bvh.leaks(), "leaks " + where);
        assertEquals(0, brute.leaks(), "leaks by brute force " + where);
        assertTrue(bvh.textbookLeaks() > 0, "the seams are probed: the textbook test leaks " + where);
    }
}
