package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The flattened BVH as its node view shows it: a sound tree over exactly the primitives it was given. */
class BVHStructureTest {
    @ParameterizedTest(name = "{0} boxes, {1} bins, leaves of at most {2}")
    @CsvSource({"1, 16, 4", "2, 2, 1", "500, 16, 4", "500, 32, 16", "2000, 8, 2"})
    void leavesPartitionThePrimitivesAndBoxesNest(int count, int bins, int maxLeafSize) {
        double[] boxes = randomBoxes(count, new SplittableRandom(count));
        BVH bvh = BVH.build(boxes, bins, maxLeafSize);
        List<BVHNode> nodes = bvh.nodes();
        assertEquals(bvh.nodeCount(), nodes.size());
        assertEquals(count, bvh.primitiveCount());

        int[] seen = new int[count];
        int leaves = 0;
        for (int i = 0; i < nodes.size(); i++) {
            BVHNode node = nodes.get(i);
            if (node.isLeaf()) {
                leaves++;
                for (int k = node.firstPrimitive(); k < node.firstPrimitive() + node.primitiveCount(); k++) {
                    int p = bvh.primitiveAt(k);
                    seen[p]++;
                    assertTrue(contains(node.bounds(), boxes, p), "leaf " + i + " holds primitive " + p);
                }
            } else {
                // Two to four children, depth-first: the first child follows its parent, the others come in order.
                List<Integer> children = node.children();
                assertTrue(children.size() >= 2 && children.size() <= BVH.WIDTH, "node " + i + " " + children);
                assertEquals(i + 1, children.get(0), "first child of " + i);
                for (int c = 0; c < children.size(); c++) {
                    if (c > 0) assertTrue(children.get(c) > children.get(c - 1), "children of " + i + " in order");
                    assertTrue(
                            encloses(node.bounds(), nodes.get(children.get(c)).bounds()), "child " + c + " of " + i);
                }
            }
        }
        assertEquals(bvh.leafCount(), leaves);
        for (int p = 0; p < count; p++) assertEquals(1, seen[p], "primitive " + p + " in exactly one leaf");
        assertEquals(nodes.get(0).bounds(), bvh.bounds());
    }

    /**
     * Every node's box is exactly the union of its primitives' boxes rounded outward to floats: the build derives a
     * child's box from its parent's bins rather than from a pass over its primitives, and a box too large would
     * cost only speed, so no query test would notice.
     */
    @ParameterizedTest(name = "{0} boxes, {1} bins, leaves of at most {2}")
    @CsvSource({"500, 16, 4", "3000, 8, 2", "3000, 32, 1"})
    void everyBoxIsTheTightestFloatBoxAroundItsPrimitives(int count, int bins, int maxLeafSize) {
        double[] boxes = randomBoxes(count, new SplittableRandom(31L * count + bins));
        BVH bvh = BVH.build(boxes, bins, maxLeafSize);
        union(bvh.nodes(), 0, bvh, boxes);
    }

    /** The union of the primitives' boxes below node {@code i}, checked against the node's box on the way. */
    private static double[] union(List<BVHNode> nodes, int i, BVH bvh, double[] boxes) {
        BVHNode node = nodes.get(i);
        double[] u = {
            Double.POSITIVE_INFINITY,
            Double.POSITIVE_INFINITY,
            Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY
        };
        if (node.isLeaf()) {
            for (int k = node.firstPrimitive(); k < node.firstPrimitive() + node.primitiveCount(); k++) {
                int o = 6 * bvh.primitiveAt(k);
                for (int a = 0; a < 3; a++) {
                    u[a] = Math.min(u[a], boxes[o + a]);
                    u[3 + a] = Math.max(u[3 + a], boxes[o + 3 + a]);
                }
            }
        } else {
            for (int child : node.children()) {
                double[] c = union(nodes, child, bvh, boxes);
                for (int a = 0; a < 3; a++) {
                    u[a] = Math.min(u[a], c[a]);
                    u[3 + a] = Math.max(u[3 + a], c[3 + a]);
                }
            }
        }
        BoundingBox b = node.bounds();
        double[] expected = {
            FloatBoxes.floatBelow(u[0]), FloatBoxes.floatBelow(u[1]), FloatBoxes.floatBelow(u[2]),
            FloatBoxes.floatAbove(u[3]), FloatBoxes.floatAbove(u[4]), FloatBoxes.floatAbove(u[5])
        };
        double[] actual = {b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ};
        assertArrayEquals(expected, actual, "node " + i);
        return u;
    }

    @Test
    void coincidentCentroidsAreSplitByCountSoLeavesStaySmall() {
        double[] boxes = new double[6 * 100];
        for (int p = 0; p < 100; p++) System.arraycopy(new double[] {0, 0, 0, 1, 1, 1}, 0, boxes, 6 * p, 6);
        BVH bvh = BVH.build(boxes, 16, 4);
        for (BVHNode node : bvh.nodes()) {
            assertTrue(!node.isLeaf() || node.primitiveCount() <= 4, node.toString());
        }
    }

    private static double[] randomBoxes(int count, SplittableRandom random) {
        double[] boxes = new double[6 * count];
        for (int p = 0; p < count; p++) {
            for (int a = 0; a < 3; a++) {
                double lo = 100 * random.nextDouble() - 50;
                boxes[6 * p + a] = lo;
                boxes[6 * p + 3 + a] = lo + random.nextDouble() * (random.nextInt(10) == 0 ? 30 : 2);
            }
        }
        return boxes;
    }

    private static boolean contains(BoundingBox b, double[] boxes, int p) {
        int o = 6 * p;
        return b.minX <= boxes[o]
                && b.minY <= boxes[o + 1]
                && b.minZ <= boxes[o + 2]
                && b.maxX >= boxes[o + 3]
                && b.maxY >= boxes[o + 4]
                && b.maxZ >= boxes[o + 5];
    }

    private static boolean encloses(BoundingBox outer, BoundingBox inner) {
        return outer.minX <= inner.minX
                && outer.minY <= inner.minY
                && outer.minZ <= inner.minZ
                && outer.maxX >= inner.maxX
                && outer.maxY >= inner.maxY
                && outer.maxZ >= inner.maxZ;
    }
}
