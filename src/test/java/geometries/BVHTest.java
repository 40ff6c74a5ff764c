package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Structural tests of {@link BVH}: every primitive once, boxes nest, leaves bounded, depth bounded. */
class BVHTest {

    @Test
    void buildParametersAreValidated() {
        double[] one = {0, 0, 0, 1, 1, 1};
        Hits.assertRejected(() -> BVH.build(one, 1, 4), "bins", "1");
        Hits.assertRejected(() -> BVH.build(one, 257, 4), "bins", "257");
        Hits.assertRejected(() -> BVH.build(one, 16, 0), "maxLeafSize", "0");
        Hits.assertRejected(() -> BVH.build(one, 16, 65), "maxLeafSize", "65");
        Hits.assertRejected(() -> BVH.build(new double[] {0, 0, 0, 1, 1}, 16, 4), "6 values");
        // Empty by less than a float's step: the float boxes the builder reads would not show it.
        Hits.assertRejected(() -> BVH.build(new double[] {1 + 1e-12, 0, 0, 1, 1, 1}, 16, 4), "empty", "primitive 0");
        assertThrows(IllegalArgumentException.class, () -> BVH.build(one, 16, 4).node(1));
    }

    /**
     * Among many float boxes (checked in chunks on all cores), the first bad one is named, whichever chunk holds it:
     * a NaN in a later chunk and an empty box in an earlier one.
     */
    @Test
    void theFirstBadBoxOfManyIsNamed() {
        int n = 300_000;
        float[] boxes = new float[BVH.BOX_STRIDE * n];
        for (int p = 0; p < n; p++) {
            for (int a = 0; a < 3; a++) {
                boxes[BVH.BOX_STRIDE * p + a] = p;
                boxes[BVH.BOX_STRIDE * p + BVH.BOX_MAX + a] = p + 1;
            }
        }
        boxes[BVH.BOX_STRIDE * 250_001 + 1] = Float.NaN;
        boxes[BVH.BOX_STRIDE * 70_003 + BVH.BOX_MAX + 2] = 70_002;
        for (boolean parallel : new boolean[] {false, true}) {
            Hits.assertRejected(
                    () -> BVH.build(boxes.clone(), 16, 4, parallel, null), "empty or NaN", "primitive 70003", "axis 2");
        }
    }

    /**
     * The padding before the first node fits the JVM running the tests: where G1 puts a large array at a region's
     * start, its data begins the array's base offset in, and the first node must then start on a 64-byte line.
     */
    @Test
    void nodesStartOnACacheLineWhereALargeArrayStartsOnARegion() {
        assertEquals(0, (sun.misc.Unsafe.ARRAY_FLOAT_BASE_OFFSET + Float.BYTES * BVH.FIRST_NODE) % 64);
        assertEquals(0, Float.BYTES * BVH.NODE_STRIDE % 64, "every node a whole number of lines");
    }

    @Test
    void singlePrimitiveIsOneLeaf() {
        BVH bvh = BVH.build(new double[] {0, 0, 0, 1, 2, 3}, 16, 4);
        assertEquals(1, bvh.nodeCount());
        assertEquals(1, bvh.leafCount());
        assertEquals(0, bvh.depth());
        BVHNode root = bvh.node(0);
        assertTrue(root.isLeaf());
        assertEquals(new BoundingBox(0, 0, 0, 1, 2, 3), root.bounds());
        assertEquals(0, bvh.primitiveAt(0));
    }

    /**
     * A group small enough to be a leaf splits where the SAH finds it cheaper (four small boxes at the corners of a
     * square: the children's boxes are a sliver of the node's) and stays one where no split pays (four boxes almost
     * on top of each other), whether or not the build skips binning the leaves it can price without bins.
     */
    @Test
    void aSmallGroupSplitsOnlyWhereTheSahSaysSo() {
        double s = 0.01;
        double[] corners = {0, 0, 0, s, s, s, 1, 0, 0, 1 + s, s, s, 0, 1, 0, s, 1 + s, s, 1, 1, 0, 1 + s, 1 + s, s};
        BVH spread = BVH.build(corners, 16, 4);
        assertTrue(spread.leafCount() > 1, "four far-apart boxes split: " + spread.leafCount() + " leaf");
        double[] stacked = {0, 0, 0, 1, 1, 1, s, 0, 0, 1 + s, 1, 1, 0, s, 0, 1, 1 + s, 1, s, s, 0, 1 + s, 1 + s, 1};
        BVH together = BVH.build(stacked, 16, 4);
        assertEquals(1, together.leafCount(), "four overlapping boxes stay one leaf");
    }

    /**
     * Where leaves are filled ({@link LeafFilter}: the accelerator's tree), every node of at most that many primitives,
     * all of which the filter takes, is a leaf even where the SAH would split it, but never past the largest leaf
     * allowed.
     */
    @Test
    void filledLeavesTakeEverySmallGroupUpToTheLargestLeafAllowed() {
        double s = 0.01;
        double[] corners = {0, 0, 0, s, s, s, 1, 0, 0, 1 + s, s, s, 0, 1, 0, s, 1 + s, s, 1, 1, 0, 1 + s, 1 + s, s};
        assertEquals(
                1,
                BVH.build(FloatBoxes.roundedOutward(corners), 16, 4, new FilledLeaves(4, null), false, null)
                        .leafCount());
        assertEquals(
                2,
                BVH.build(FloatBoxes.roundedOutward(corners), 16, 2, new FilledLeaves(4, null), false, null)
                        .leafCount());
        assertTrue(BVH.build(FloatBoxes.roundedOutward(corners), 16, 4, FilledLeaves.NONE, false, null)
                        .leafCount()
                > 1);
        assertTrue(BVH.build(FloatBoxes.roundedOutward(corners), 16, 4, new FilledLeaves(3, null), false, null)
                        .leafCount()
                > 1);
        // A group with a primitive the filter does not take (a sphere, say) is left to the SAH.
        FilledLeaves oneNotFiltered = new FilledLeaves(4, new boolean[] {true, true, false, true});
        assertTrue(BVH.build(FloatBoxes.roundedOutward(corners), 16, 4, oneNotFiltered, false, null)
                        .leafCount()
                > 1);
        FilledLeaves allFiltered = new FilledLeaves(4, new boolean[] {true, true, true, true});
        assertEquals(
                1,
                BVH.build(FloatBoxes.roundedOutward(corners), 16, 4, allFiltered, false, null)
                        .leafCount());
    }

    static Stream<Arguments> cases() {
        return LongStream.range(0, 8)
                .mapToObj(i -> Arguments.of(0xB7L + 13L * i, (int) (1 + i * i * 37), (int) (1 + i % 4)));
    }

    @ParameterizedTest(name = "seed {0}, {1} boxes, leaves <= {2}")
    @MethodSource("cases")
    void structureIsConsistent(long seed, int n, int maxLeaf) {
        Random random = new Random(seed);
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            // some clusters of identical boxes (coincident centroids) among spread ones
            boolean clustered = random.nextInt(5) == 0;
            for (int a = 0; a < 3; a++) {
                double lo = clustered ? 7 : random.nextGaussian() * 50;
                boxes[6 * i + a] = lo;
                boxes[6 * i + 3 + a] = lo + (clustered ? 1 : random.nextDouble() * 5);
            }
        }
        BVH bvh = BVH.build(boxes, 16, maxLeaf);
        assertEquals(n, bvh.primitiveCount());
        boolean[] seen = new boolean[n];
        int[] leafPrimitives = {0};
        check(bvh, 0, boxes, seen, leafPrimitives, maxLeaf, 0);
        assertEquals(n, leafPrimitives[0], "leaves hold every primitive once");
        for (int i = 0; i < n; i++) assertTrue(seen[i], "primitive " + i + " in a leaf (seed " + seed + ")");
        assertTrue(bvh.depth() <= BVH.MAX_DEPTH);
        assertEquals(bvh.binaryNodeCount(), 2 * bvh.leafCount() - 1, "collapsed from a binary tree");
        // Every 4-wide node absorbs at least one binary interior node.
        assertTrue(bvh.nodeCount() - bvh.leafCount() <= bvh.leafCount() - 1, "fewer interior nodes than binary");
    }

    /**
     * The builder reads the boxes rounded outward to floats: far from the origin they lie on float's coarse grid, and
     * beyond float's range their bounds are infinite. Every primitive still lands in exactly one leaf that holds its
     * box: a primitive binned on one side and partitioned to the other would leave a child empty (the build failed on
     * its node arrays when the partition summed a box's float bounds in float and the binning in double).
     */
    @ParameterizedTest(name = "at {0} + [0, {1}], sizes up to {2}, parallel {3}")
    @MethodSource("extremeBoxes")
    void boxesOnFloatsCoarseGridOrBeyondItsRangeStillMakeATree(
            double offset, double spread, double size, boolean parallel) {
        Random random = new Random(Double.hashCode(offset) ^ Double.hashCode(spread));
        int n = 3000;
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                double lo = offset + random.nextDouble() * spread;
                boxes[6 * i + a] = lo;
                boxes[6 * i + 3 + a] = lo + random.nextDouble() * size;
            }
        }
        BVH bvh = BVH.build(boxes, 16, 4, parallel);
        boolean[] seen = new boolean[n];
        int[] leafPrimitives = {0};
        check(bvh, 0, boxes, seen, leafPrimitives, 4, 0);
        assertEquals(n, leafPrimitives[0], "leaves hold every primitive once");
    }

    static Stream<Arguments> extremeBoxes() {
        return Stream.of(
                Arguments.of(1e6, 10.0, 0.1, false),
                Arguments.of(-3e7, 100.0, 1.0, true),
                Arguments.of(0.0, 1e39, 1e38, false),
                Arguments.of(-1e300, 1e300, 1e299, false),
                Arguments.of(-1e300, 1e300, 1e299, true));
    }

    /** Walks the subtree at {@code node}; returns the index after it (depth-first layout). */
    private static int check(BVH bvh, int node, double[] boxes, boolean[] seen, int[] count, int maxLeaf, int depth) {
        BVHNode n = bvh.node(node);
        BoundingBox b = n.bounds();
        if (n.isLeaf()) {
            int centroidsDiffer = 0;
            for (int k = n.firstPrimitive(); k < n.firstPrimitive() + n.primitiveCount(); k++) {
                int p = bvh.primitiveAt(k);
                assertTrue(!seen[p], "primitive " + p + " in two leaves");
                seen[p] = true;
                count[0]++;
                assertTrue(
                        b.minX <= boxes[6 * p]
                                && b.minY <= boxes[6 * p + 1]
                                && b.minZ <= boxes[6 * p + 2]
                                && b.maxX >= boxes[6 * p + 3]
                                && b.maxY >= boxes[6 * p + 4]
                                && b.maxZ >= boxes[6 * p + 5],
                        "leaf box holds primitive " + p);
                if (boxes[6 * p] != boxes[6 * bvh.primitiveAt(n.firstPrimitive())]) centroidsDiffer++;
            }
            // bigger leaves only where the SAH says so and never beyond the limit unless centroids coincide
            assertTrue(
                    n.primitiveCount() <= maxLeaf || centroidsDiffer == 0 || depth == BVH.MAX_DEPTH,
                    "leaf of " + n.primitiveCount());
            return node + 1;
        }
        assertTrue(n.children().size() >= 2 && n.children().size() <= BVH.WIDTH, "2 to " + BVH.WIDTH + " children");
        // first child follows its parent; each further child follows the subtree of the one before
        int next = node + 1;
        for (int child : n.children()) {
            assertEquals(next, child, "child after the subtree before it");
            BoundingBox c = bvh.node(child).bounds();
            assertEquals(b, b.union(c), "parent box holds child " + child);
            next = check(bvh, child, boxes, seen, count, maxLeaf, depth + 1);
        }
        return next;
    }

    /**
     * The parallel build (top split on the calling thread, subtrees of up to PARALLEL_GRAIN primitives on the
     * fork/join pool) gives the very tree the sequential build gives: same nodes, same leaf order, same statistics,
     * on random boxes (clusters, duplicates, flat boxes) and on a mesh, each large enough to take the parallel path.
     */
    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3})
    void theParallelBuildIsTheSequentialBuild(long seed) {
        java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
        int n = 2 * BVH.PARALLEL_GRAIN + random.nextInt(BVH.PARALLEL_GRAIN);
        double[] boxes = new double[6 * n];
        for (int p = 0; p < n; p++) {
            int cluster = random.nextInt(8);
            for (int a = 0; a < 3; a++) {
                double lo = random.nextInt(5) == 0 ? cluster : cluster + 10 * random.nextDouble();
                double size = random.nextInt(4) == 0 ? 0 : random.nextDouble() * 0.1;
                boxes[6 * p + a] = lo;
                boxes[6 * p + 3 + a] = lo + size;
            }
        }
        assertSameTree(BVH.build(boxes, 16, 4, false), BVH.build(boxes, 16, 4, true));
    }

    /**
     * Every parallel step of a build (the tree's top, a large mesh's boxes and layout, the collapse) runs in the
     * build's pool, none in the JDK's common pool, and the pool's workers end soon after: the JDK keeps idle workers
     * for 60 s, and a host that waits for a program's threads, such as {@code mvn exec:java}, waited 15 s after every
     * render for them.
     */
    @Test
    void theBuildsWorkersEndWhenIdle() throws InterruptedException {
        int common = java.util.concurrent.ForkJoinPool.commonPool().getPoolSize();
        Mesh mesh = Meshes.heightfield(185); // 68,450 triangles: boxes and layout in parallel
        Accelerator.build(mesh, true);
        assertTrue(BuildPool.threads() > 0 || Runtime.getRuntime().availableProcessors() == 1);
        assertTrue(java.util.concurrent.ForkJoinPool.commonPool().getPoolSize() <= common, "the common pool was used");
        long deadline = System.nanoTime() + (BuildPool.IDLE_SECONDS + 9) * 1_000_000_000L;
        while (BuildPool.threads() > 0 && System.nanoTime() < deadline) Thread.sleep(50);
        assertEquals(0, BuildPool.threads(), "workers still alive 10 s after the build");
    }

    /**
     * A second group of primitives (the clear surfaces of Accelerator's shadow queries) gets root slots of its own:
     * the primitives under the slots {@code secondGroupSlots} names are exactly the group, the parallel build gives
     * the sequential tree, and an empty or full group builds the plain tree.
     */
    @ParameterizedTest
    @ValueSource(longs = {4, 5})
    void aSecondGroupHasRootSlotsOfItsOwn(long seed) {
        java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
        int n = 2 * BVH.PARALLEL_GRAIN + random.nextInt(BVH.PARALLEL_GRAIN);
        double[] boxes = new double[6 * n];
        boolean[] group = new boolean[n];
        for (int p = 0; p < n; p++) {
            group[p] = random.nextInt(7) == 0;
            for (int a = 0; a < 3; a++) {
                double lo = random.nextDouble() * 100;
                boxes[6 * p + a] = lo;
                boxes[6 * p + 3 + a] = lo + random.nextDouble() * (group[p] ? 20 : 2);
            }
        }
        BVH sequential = BVH.build(boxes, 16, 4, false, group);
        assertSameTree(sequential, BVH.build(boxes, 16, 4, true, group));
        int slots = sequential.secondGroupSlots;
        assertTrue(slots != 0, "the group has slots");
        java.util.List<Integer> children = sequential.node(0).children();
        for (int c = 0; c < children.size(); c++) {
            boolean inGroup = (slots >> c & 1) != 0;
            for (int p : primitivesUnder(sequential, children.get(c))) {
                assertEquals(inGroup, group[p], "primitive " + p + " under root slot " + c);
            }
        }
        BVH plain = BVH.build(boxes, 16, 4, false);
        assertSameTree(plain, BVH.build(boxes, 16, 4, false, new boolean[n]));
        boolean[] all = new boolean[n];
        java.util.Arrays.fill(all, true);
        assertSameTree(plain, BVH.build(boxes, 16, 4, false, all));
        assertEquals(0, plain.secondGroupSlots);
    }

    private static java.util.List<Integer> primitivesUnder(BVH bvh, int node) {
        java.util.List<Integer> list = new java.util.ArrayList<>();
        java.util.List<BVHNode> nodes = bvh.nodes();
        java.util.ArrayDeque<Integer> todo = new java.util.ArrayDeque<>(java.util.List.of(node));
        while (!todo.isEmpty()) {
            BVHNode n = nodes.get(todo.pop());
            if (n.isLeaf()) {
                for (int k = 0; k < n.primitiveCount(); k++) list.add(bvh.primitiveAt(n.firstPrimitive() + k));
            } else {
                todo.addAll(n.children());
            }
        }
        return list;
    }

    private static void assertSameTree(BVH sequential, BVH parallel) {
        assertArrayEquals(sequential.nodes, parallel.nodes);
        assertArrayEquals(sequential.order, parallel.order);
        assertArrayEquals(sequential.rootBounds, parallel.rootBounds);
        assertEquals(sequential.rootLink, parallel.rootLink);
        assertEquals(sequential.rootCount, parallel.rootCount);
        assertEquals(sequential.nodeCount(), parallel.nodeCount());
        assertEquals(sequential.binaryNodeCount(), parallel.binaryNodeCount());
        assertEquals(sequential.leafCount(), parallel.leafCount());
        assertEquals(sequential.depth(), parallel.depth());
    }
}
