package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The collapse of a binary tree into wide nodes: below {@link WideCollapser#GREEDY_ABOVE} leaves it is the one of
 * least total wide-node area, checked against every collapse of small trees and against the greedy collapse of larger
 * ones.
 */
class WideCollapserTest {

    /** Seeded binary trees of 9 to 16 leaves (one box per leaf), small enough to try every collapse. */
    static Stream<Arguments> smallTrees() {
        return IntStream.range(0, 24).mapToObj(i -> Arguments.of(0x5EEDL + 31L * i, 9 + i % 8));
    }

    @ParameterizedTest(name = "seed {0}, {1} leaves")
    @MethodSource("smallTrees")
    void theCollapseHasTheLeastAreaOfAllCollapses(long seed, int n) {
        BvhBuilder b = builder(randomBoxes(seed, n), 1);
        WideCollapser c = new WideCollapser(b, false);
        double collapsed = wideNodeArea(b, c, 0);
        double least = leastAreaOfAllCollapses(b);
        assertEquals(least, collapsed, 1e-5 * least, "seed " + seed);
    }

    /** Seeded scenes of up to 512 leaves, optimal throughout, and of more, where the top is greedy. */
    static Stream<Arguments> largerTrees() {
        return IntStream.range(0, 12).mapToObj(i -> Arguments.of(0xC011L + 7L * i, 100 + 350 * i));
    }

    @ParameterizedTest(name = "seed {0}, {1} boxes")
    @MethodSource("largerTrees")
    void theCollapseHasNoMoreAreaThanTheGreedyOne(long seed, int n) {
        BvhBuilder b = builder(randomBoxes(seed, n), 4);
        double optimal = wideNodeArea(b, new WideCollapser(b, false), 0);
        double greedy = wideNodeArea(b, new WideCollapser(b, false, 0), 0);
        assertTrue(optimal <= greedy * (1 + 1e-6), optimal + " > greedy " + greedy + " (seed " + seed + ")");
    }

    /** Near the leaves the greedy collapse leaves nodes part empty; the optimal one needs fewer wide nodes here. */
    @Test
    void aMeshNeedsFewerWideNodesThanGreedily() {
        // The triangles' boxes as the accelerator collects them (5,120 of an icosphere), checked as a build checks
        // them.
        PrimitiveCollector collector = new PrimitiveCollector();
        collector.collect(Meshes.icosphere(4));
        float[] boxes = collector.boxes();
        FloatBoxes.checkAndNormalize(boxes, false);
        BvhBuilder b = new BvhBuilder(boxes, 16, 4, FilledLeaves.NONE, false, null);
        int optimal = new WideCollapser(b, false).countWideNodes(0);
        int greedy = new WideCollapser(b, false, 0).countWideNodes(0);
        assertTrue(optimal < greedy, optimal + " wide nodes, greedily " + greedy);
    }

    private static double[] randomBoxes(long seed, int n) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] boxes = new double[6 * n];
        for (int p = 0; p < n; p++) {
            for (int a = 0; a < 3; a++) {
                double lo = random.nextDouble() * 100;
                boxes[6 * p + a] = lo;
                boxes[6 * p + 3 + a] = lo + random.nextDouble() * (random.nextInt(8) == 0 ? 40 : 4);
            }
        }
        return boxes;
    }

    private static BvhBuilder builder(double[] boxes, int maxLeafSize) {
        return new BvhBuilder(FloatBoxes.roundedOutward(boxes), 16, maxLeafSize, FilledLeaves.NONE, false, null);
    }

    /** The total area of the binary nodes that become wide nodes, from {@code binary} down, as {@code c} opens them. */
    private static double wideNodeArea(BvhBuilder b, WideCollapser c, int binary) {
        int[] children = new int[BVH.WIDTH];
        int n = c.open(binary, children);
        double sum = b.area(binary);
        for (int i = 0; i < n; i++) {
            if (!b.isLeaf(children[i])) sum += wideNodeArea(b, c, children[i]);
        }
        return sum;
    }

    /**
     * The oracle: every set of interior nodes that holds the root and gives no wide node more than eight children
     * (each wide node's children are the first leaves or set members below it), and the least total area of them.
     */
    private static double leastAreaOfAllCollapses(BvhBuilder b) {
        int[] interior =
                IntStream.range(1, b.nodeCount).filter(i -> !b.isLeaf(i)).toArray();
        double least = Double.POSITIVE_INFINITY;
        boolean[] wide = new boolean[b.nodeCount];
        for (long set = 0; set < 1L << interior.length; set++) {
            Arrays.fill(wide, false);
            wide[0] = true;
            double sum = b.area(0);
            for (int k = 0; k < interior.length; k++) {
                if ((set >> k & 1) != 0) {
                    wide[interior[k]] = true;
                    sum += b.area(interior[k]);
                }
            }
            if (sum >= least) continue;
            boolean fits = true;
            for (int i = 0; i < b.nodeCount && fits; i++) {
                if (wide[i]) fits = slots(b, wide, i + 1) + slots(b, wide, b.data[2 * i]) <= BVH.WIDTH;
            }
            if (fits) least = sum;
        }
        return least;
    }

    /** The slots that binary node {@code node} takes in its wide parent: one if a leaf or wide, else its children's. */
    private static int slots(BvhBuilder b, boolean[] wide, int node) {
        if (b.isLeaf(node) || wide[node]) return 1;
        return slots(b, wide, node + 1) + slots(b, wide, b.data[2 * node]);
    }
}
