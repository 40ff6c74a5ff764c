package geometries;

import static geometries.CompiledPrimitives.EDGES;
import static geometries.CompiledPrimitives.INDEX;
import static geometries.CompiledPrimitives.INFO;
import static geometries.CompiledPrimitives.OBJECT;
import static geometries.CompiledPrimitives.OWNER;
import static geometries.CompiledPrimitives.PART;

import primitives.Ray;

/**
 * The closest-hit search of an {@link Accelerator}: down its BVH nearest child first, or, without a BVH, over every
 * primitive in turn (brute force), with the unbounded primitives tested first. Of hits at the same distance the one
 * added first wins (insertion index as tie-break), whatever the visiting order, so both searches return the same
 * primitive and the same distance bit for bit.
 */
final class ClosestHitTraversal {

    // The arrays of CompiledPrimitives this search reads, copied into final fields of the class that runs the
    // loops: a loop reaches each in one load from this (loading them into locals measured about 2% slower on the
    // street; reading them through the CompiledPrimitives object would add a load per access).
    private final int boundedCount;
    private final double[] triangles;
    private final int[] info;
    private final Geometry[] geometries;
    private final Intersectable[] objects;
    private final Intersectable[] unbounded;
    /** The BVH, or null for brute-force search. */
    private final BVH bvh;
    /** See {@link CompiledPrimitives#searchesTree}. */
    private final boolean searchesTree;

    /** See {@link CompiledPrimitives#leafFilter}. */
    private final LeafFilter leafFilter;

    ClosestHitTraversal(CompiledPrimitives primitives, BVH bvh) {
        boundedCount = primitives.boundedCount;
        triangles = primitives.triangles;
        info = primitives.info;
        geometries = primitives.geometries;
        objects = primitives.objects;
        unbounded = primitives.unbounded;
        this.bvh = bvh;
        searchesTree = primitives.searchesTree;
        leafFilter = primitives.leafFilter;
    }

    /** See {@link Accelerator#intersect}. */
    boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        hit.withoutBvh = bvh == null;
        int best = Integer.MAX_VALUE;
        // Where the best hit so far is a triangle, its slot: its geometry and part are filled in at the end.
        int bestTriangle = -1;
        // Where it is another bounded shape, its slot (an instance among them leaves its mark in the record).
        int bestObject = -1;
        double tieLimit = tMax;
        long tests = 0;
        for (int j = 0; j < unbounded.length; j++) {
            tests++;
            if (unbounded[j].intersect(ray, tMin, tMax, hit)) {
                tMax = hit.t;
                tieLimit = Math.nextUp(tMax);
                best = boundedCount + j;
                bestObject = -1;
            }
        }
        if (!searchesTree) {
            for (int k = 0; k < boundedCount; k++) {
                tests++;
                if (testPrimitive(k, ray, tMin, info[INFO * k + INDEX] < best ? tieLimit : tMax, hit)) {
                    tMax = hit.t;
                    tieLimit = Math.nextUp(tMax);
                    best = info[INFO * k + INDEX];
                    bestTriangle = info[INFO * k + EDGES] == OBJECT ? -1 : k;
                    bestObject = info[INFO * k + EDGES] == OBJECT ? k : -1;
                }
            }
        } else if (boundedCount > 0) {
            final float[] nodes = bvh.nodes;
            final WideBoxTest boxTest = WideBoxTest.SELECTED;
            final int[] stack = hit.stack;
            final double[] stackEntry = hit.stackEntry;
            final float[] entries = hit.entries;
            final RaySlabs slabs = hit.slabs;
            slabs.set(ray);
            final float tMinF = RaySlabs.below(tMin);
            float tMaxF = RaySlabs.above(tMax); // follows tMax as the closest hit moves it
            long visits = 1; // the root, as the statistics have always counted it
            int sp = 0;
            int link = bvh.rootLink, count = bvh.rootCount;
            // No test of the root's own box: visiting the root tests its children's boxes, which lie inside it.
            boolean more = true;
            while (more) {
                if (count > 0 && CompiledPrimitives.isFilled(info[INFO * link + EDGES])) {
                    tests += count;
                    int k = filledLeafHit(link, count, ray, tMin, tMax, tieLimit, best, hit);
                    if (k >= 0) {
                        tMax = hit.t;
                        tMaxF = RaySlabs.above(tMax);
                        tieLimit = Math.nextUp(tMax);
                        best = info[INFO * k + INDEX];
                        bestTriangle = k;
                        bestObject = -1;
                    }
                } else if (count > 0) {
                    for (int k = link, end = link + count; k < end; k++) {
                        tests++;
                        if (testPrimitive(k, ray, tMin, info[INFO * k + INDEX] < best ? tieLimit : tMax, hit)) {
                            tMax = hit.t;
                            tMaxF = RaySlabs.above(tMax);
                            tieLimit = Math.nextUp(tMax);
                            best = info[INFO * k + INDEX];
                            bestTriangle = info[INFO * k + EDGES] == OBJECT ? -1 : k;
                            bestObject = info[INFO * k + EDGES] == OBJECT ? k : -1;
                        }
                    }
                } else {
                    // All children's boxes come with this node: test them, go to the nearest, postpone the others.
                    int o = BVH.nodeOffset(link);
                    visits += BVH.WIDTH;
                    int mask = boxTest.test(nodes, o, slabs, tMinF, tMaxF, entries);
                    if (mask != 0) {
                        int rest = mask & (mask - 1);
                        if (rest == 0) {
                            // One child hit: no stack traffic.
                            int only = Integer.numberOfTrailingZeros(mask);
                            link = Float.floatToRawIntBits(nodes[o + BVH.LINK + only]);
                            count = Float.floatToRawIntBits(nodes[o + BVH.COUNT + only]);
                            continue;
                        }
                        if ((rest & (rest - 1)) == 0) {
                            // Two children hit (the commonest multi-hit case): one comparison orders them; push
                            // the farther, take the nearer (the later one on a tie).
                            int a = Integer.numberOfTrailingZeros(mask), b = Integer.numberOfTrailingZeros(rest);
                            float ea = entries[a], eb = entries[b];
                            int far = a, near = b;
                            float farEntry = ea;
                            if (ea < eb) {
                                far = b;
                                near = a;
                                farEntry = eb;
                            }
                            push(stack, stackEntry, sp++, nodes, o, far, farEntry);
                            link = Float.floatToRawIntBits(nodes[o + BVH.LINK + near]);
                            count = Float.floatToRawIntBits(nodes[o + BVH.COUNT + near]);
                            continue;
                        }
                        // Three or more: insert them into the stack farthest first, then take the nearest off.
                        sp = pushSorted(stack, stackEntry, sp, nodes, o, mask, entries) - 1;
                        link = stack[2 * sp];
                        count = stack[2 * sp + 1];
                        continue;
                    }
                }
                // Resume with the most recently postponed child that the closest hit has not put out of reach.
                more = false;
                while (sp > 0) {
                    if (stackEntry[--sp] <= tMax) {
                        link = stack[2 * sp];
                        count = stack[2 * sp + 1];
                        more = true;
                        break;
                    }
                }
            }
            hit.nodeVisits += visits;
        }
        hit.primitiveTests += tests;
        if (best == Integer.MAX_VALUE) return false;
        if (bestTriangle >= 0) {
            hit.geometry = geometries[info[INFO * bestTriangle + OWNER]];
            hit.part = info[INFO * bestTriangle + PART];
        }
        // Only an instance marks the record: a triangle, another shape or unbounded geometry that ended closer than
        // an instance hit earlier in the search clears the mark.
        if (bestObject < 0 || !(objects[bestObject] instanceof Instance)) hit.instance = null;
        hit.primitiveIndex = best;
        return true;
    }

    /**
     * Tests bounded primitive {@code k}. A triangle leaves the record's geometry and part alone (the caller fills
     * them for the final hit only: fewer arrays touched per test); other shapes fill them.
     */
    private boolean testPrimitive(int k, Ray ray, double tMin, double tMax, HitRecord hit) {
        int edges = info[INFO * k + EDGES];
        if (edges == OBJECT) return objects[k].intersect(ray, tMin, tMax, hit);
        int o = 9 * k;
        return WatertightTriangle.intersect(triangles, o, o + 3, o + 6, edges, ray, tMin, tMax, hit);
    }

    /**
     * Tests the filled leaf of {@code count} at {@code link} (triangles of a large mesh only) as the search's loop
     * tests a leaf, and returns the position of the triangle it ends on, whose hit is in the record, or -1 if none is
     * closer. Only the filter's candidates are tested (in the leaf's lanes, in leaf order); the rest would be missed by
     * their own test. Its own method, called from the loop: the loop stays as small as it was for other leaves.
     */
    private int filledLeafHit(
            int link, int count, Ray ray, double tMin, double tMax, double tieLimit, int best, HitRecord hit) {
        int candidates = count > 1 ? leafFilter.candidates(triangles, 9 * link, count, ray) & ((1 << count) - 1) : 1;
        int found = -1;
        for (; candidates != 0; candidates &= candidates - 1) {
            int i = Integer.numberOfTrailingZeros(candidates), k = link + i, index = info[INFO * k + INDEX];
            double limit = index < best ? tieLimit : tMax;
            if (CompiledPrimitives.intersectFilled(
                    triangles, link, i, count, info[INFO * k + EDGES], ray, tMin, limit, hit)) {
                tMax = hit.t;
                tieLimit = Math.nextUp(tMax);
                best = index;
                found = k;
            }
        }
        return found;
    }

    /**
     * Pushes the children of the node at {@code o} named by {@code mask} so that the nearest ends on top (the later
     * one on a tie), by insertion into the few slots above {@code sp}; returns the new stack size.
     */
    private static int pushSorted(
            int[] stack, double[] stackEntry, int sp, float[] nodes, int o, int mask, float[] entries) {
        int base = sp;
        for (; mask != 0; mask &= mask - 1) {
            int c = Integer.numberOfTrailingZeros(mask);
            float e = entries[c];
            int j = sp++;
            while (j > base && stackEntry[j - 1] < e) {
                stack[2 * j] = stack[2 * j - 2];
                stack[2 * j + 1] = stack[2 * j - 1];
                stackEntry[j] = stackEntry[j - 1];
                j--;
            }
            push(stack, stackEntry, j, nodes, o, c, e);
        }
        return sp;
    }

    /** Writes child {@code c} of the node at {@code o}, entered at {@code entry}, to stack slot {@code sp}. */
    private static void push(int[] stack, double[] stackEntry, int sp, float[] nodes, int o, int c, double entry) {
        stack[2 * sp] = Float.floatToRawIntBits(nodes[o + BVH.LINK + c]);
        stack[2 * sp + 1] = Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
        stackEntry[sp] = entry;
    }
}
