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
 * Spawned rays never hit their own surface (acne) and never start beyond a surface 1e-6 away (thin gaps), at
 * distances 1 to 1e9 from the origin, for every shape, with the BVH and by brute force. Seeded; the seed is in
 * every failure message.
 */
class SelfIntersectionTest {
    private static final double[] DISTANCES = {1, 1e3, 1e6, 1e9};
    private static final long[] SEEDS = {1, 0x5EEDL, 20261122L};

    static Stream<Arguments> shapesDistancesSeeds() {
        List<Arguments> cases = new ArrayList<>();
        for (AcneProbe.Shape shape : AcneProbe.Shape.values()) {
            for (double d : DISTANCES) for (long seed : SEEDS) cases.add(Arguments.of(shape, d, seed));
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0} at {1}, seed {2}")
    @MethodSource("shapesDistancesSeeds")
    void spawnedRaysNeverHitTheirOwnSurface(AcneProbe.Shape shape, double distance, long seed) {
        AcneProbe.Result bvh = AcneProbe.run(shape, distance, 400, seed, true);
        AcneProbe.Result brute = AcneProbe.run(shape, distance, 400, seed, false);
        String where = shape + " at " + distance + " (seed " + seed + ")";
        assertTrue(bvh.spawned() > 400, "most probes hit the shape: " + where);
        assertEquals(0, bvh.selfHits(), "self-hits " + where);
        assertEquals(0, bvh.nonFinite(), "non-finite hit records " + where);
        assertEquals(bvh, brute, "BVH and brute force agree " + where);
    }

    static Stream<Arguments> distancesSeeds() {
        List<Arguments> cases = new ArrayList<>();
        for (double d : DISTANCES) for (long seed : SEEDS) cases.add(Arguments.of(d, seed));
        return cases.stream();
    }

    @ParameterizedTest(name = "gap at {0}, seed {1}")
    @MethodSource("distancesSeeds")
    void aRayLeavingASphereFindsAConcentricSphereOneMicronAway(double distance, long seed) {
        ThinGapProbe.Result bvh = ThinGapProbe.run(distance, 1e-6, 400, seed, true);
        assertEquals(400, bvh.spawned());
        assertEquals(0, bvh.escaped(), "escaped through the gap at " + distance + " (seed " + seed + ")");
        assertEquals(0, bvh.selfHits(), "hit the inner sphere again at " + distance + " (seed " + seed + ")");
        assertEquals(bvh, ThinGapProbe.run(distance, 1e-6, 400, seed, false), "brute force agrees");
    }

    @ParameterizedTest(name = "fixed offsets fail at {0}")
    @MethodSource("distancesSeeds")
    void noFixedOffsetWorksAtEveryDistance(double distance, long seed) {
        // The comparison that motivates error-bounded offsets: 0.1 skips the gap everywhere, 1e-9 acnes far away.
        FixedOffsetBaseline.Result large = FixedOffsetBaseline.run(distance, 0.1, 1e-6, 200, seed);
        assertEquals(large.spawned(), large.escaped(), "a 0.1 offset jumps over a 1e-6 gap");
        FixedOffsetBaseline.Result small = FixedOffsetBaseline.run(distance, 1e-9, 1e-6, 200, seed);
        if (distance >= 1e9) assertTrue(small.selfHits() > 20, "a 1e-9 offset acnes at 1e9: " + small);
    }
}
