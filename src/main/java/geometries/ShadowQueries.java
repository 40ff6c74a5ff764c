package geometries;

import static geometries.CompiledPrimitives.EDGES;
import static geometries.CompiledPrimitives.INDEX;
import static geometries.CompiledPrimitives.INFO;
import static geometries.CompiledPrimitives.OBJECT;
import static geometries.CompiledPrimitives.OWNER;
import static geometries.CompiledPrimitives.PART;

import primitives.Double3;
import primitives.Ray;

/**
 * The shadow (any-hit) queries of an {@link Accelerator}: whether anything blocks a segment, and how much light
 * passes through the transparent surfaces along it. A search stops at the first opaque hit, in any order, and skips
 * clear surfaces (the BVH keeps them in a subtree of their own under the root). Before the search, the primitive
 * that blocked the previous query through the record is tested (the occluder cache); within an aimed
 * {@link ShadowBeam}, only the leaves the beam found are tested.
 *
 * <p>The public contracts are on {@link Accelerator#occludes}, {@link Accelerator#passesLight} and
 * {@link Accelerator#aimShadowBeam}, which delegate here. Beams are aimed for one such object and used only with it.
 */
final class ShadowQueries {

    // The arrays of CompiledPrimitives these queries read, copied into final fields of the class that runs the
    // loops: a loop reaches each in one load from this (loading them into locals measured about 2% slower on the
    // street; reading them through the CompiledPrimitives object would add a load per access).
    private final int boundedCount;
    private final double[] triangles;
    private final int[] info;
    private final Geometry[] geometries;
    private final Intersectable[] objects;
    private final boolean[] mayTransmit, clear;
    private final Intersectable[] unbounded;
    private final boolean[] unboundedMayTransmit, unboundedClear;
    /** The BVH, or null for brute-force search. */
    private final BVH bvh;
    /** See {@link CompiledPrimitives#searchesTree}. */
    private final boolean searchesTree;
    /** See {@link Accelerator#testsShadowPackets}. */
    final boolean testsPackets;

    /** See {@link CompiledPrimitives#leafFilter}. */
    private final LeafFilter leafFilter;

    ShadowQueries(CompiledPrimitives primitives, BVH bvh) {
        boundedCount = primitives.boundedCount;
        triangles = primitives.triangles;
        info = primitives.info;
        geometries = primitives.geometries;
        objects = primitives.objects;
        mayTransmit = primitives.mayTransmit;
        clear = primitives.clear;
        unbounded = primitives.unbounded;
        unboundedMayTransmit = primitives.unboundedMayTransmit;
        unboundedClear = primitives.unboundedClear;
        this.bvh = bvh;
        searchesTree = primitives.searchesTree;
        leafFilter = primitives.leafFilter;
        boolean objectsOnly = true;
        // Up to the first triangle (a mesh's is the first primitive: no pass over a million records).
        for (int k = 0; k < boundedCount && objectsOnly; k++) objectsOnly = info[INFO * k + EDGES] == OBJECT;
        testsPackets = !searchesTree && objectsOnly && !primitives.mayTransmit();
    }

    /**
     * See {@link Accelerator#blockShadowPacket}: each primitive the segments do not leave, against all open segments
     * (with every primitive opaque, a segment is blocked when any one blocks it, whatever the order).
     */
    void blockPacket(ShadowPacket packet, HitRecord scratch) {
        long tests = 0;
        for (Intersectable surface : unbounded) {
            if (surface == scratch.leaving) continue;
            tests += packet.open;
            surface.blockAll(packet, scratch);
        }
        for (int k = 0; k < boundedCount; k++) {
            if (leftBy(k, scratch)) continue;
            tests += packet.open;
            objects[k].blockAll(packet, scratch);
        }
        scratch.primitiveTests += tests;
    }

    /** See {@link Accelerator#occludes}. */
    boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        return anyHit(ray, tMin, tMax, scratch, false);
    }

    /** See {@link Accelerator#passesLight}. */
    boolean passesLight(Ray ray, double tMin, double tMax, HitRecord scratch) {
        scratch.transparentCount = 0;
        if (anyHit(ray, tMin, tMax, scratch, true)) {
            scratch.transmitR = scratch.transmitG = scratch.transmitB = 0;
            return false;
        }
        int count = scratch.transparentCount;
        double r = 1, g = 1, b = 1;
        if (count > 2) scratch.sortTransparentHits();
        double[] kt = scratch.transparentKt;
        for (int i = 0; i < 3 * count; i += 3) {
            r *= kt[i];
            g *= kt[i + 1];
            b *= kt[i + 2];
        }
        scratch.transmitR = r;
        scratch.transmitG = g;
        scratch.transmitB = b;
        return true;
    }

    /**
     * The shadow query within a beam: the leaves the beam found, eight boxes per test, then their primitives, as
     * the traversal would test them.
     */
    private boolean anyHitInBeam(ShadowBeam beam, Ray ray, double tMin, double tMax, HitRecord scratch) {
        if (beam.groups == 0) return false; // nothing near the beam: no set-up for the box test
        final float[] nodes = beam.leafNodes;
        final WideBoxTest boxTest = WideBoxTest.SELECTED;
        final float[] entries = scratch.entries;
        final RaySlabs slabs = scratch.slabs;
        slabs.set(ray);
        final float tMinF = RaySlabs.below(tMin), tMaxF = RaySlabs.above(tMax);
        long tests = 0;
        try {
            for (int g = 0, groups = beam.groups; g < groups; g++) {
                int o = BVH.NODE_STRIDE * g;
                scratch.nodeVisits += BVH.WIDTH;
                int mask = boxTest.test(nodes, o, slabs, tMinF, tMaxF, entries);
                for (; mask != 0; mask &= mask - 1) {
                    int c = Integer.numberOfTrailingZeros(mask);
                    int link = Float.floatToRawIntBits(nodes[o + BVH.LINK + c]);
                    int count = Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
                    if (CompiledPrimitives.isFilled(info[INFO * link + EDGES])) {
                        if (filledLeafBlocks(link, count, true, ray, tMin, tMax, scratch)) return true;
                        continue;
                    }
                    for (int k = link, end = link + count; k < end; k++) {
                        if (clear[k] || leftBy(k, scratch)) continue;
                        tests++;
                        if (blocks(k, mayTransmit[k], ray, tMin, tMax, scratch)) {
                            if (!mayTransmit[k]) scratch.occluder = k;
                            return true;
                        }
                    }
                }
            }
            return false;
        } finally {
            scratch.primitiveTests += tests;
        }
    }

    /**
     * Any-hit search; returns true at the first blocking hit. With {@code honourTransparency}, hits on transparent
     * surfaces do not block but are collected in the scratch record.
     */
    private boolean anyHit(Ray ray, double tMin, double tMax, HitRecord scratch, boolean honourTransparency) {
        scratch.withoutBvh = bvh == null;
        scratch.occluder = -1;
        if (blockedByHint(ray, tMin, tMax, scratch)) return true;
        long tests = 0;
        try {
            for (int j = 0; j < unbounded.length; j++) {
                if (honourTransparency && unboundedClear[j] || unbounded[j] == scratch.leaving) continue;
                tests++;
                boolean pass = honourTransparency && unboundedMayTransmit[j];
                if (blocks(unbounded[j], boundedCount + j, pass, ray, tMin, tMax, scratch)) return true;
            }
            if (!searchesTree) {
                for (int k = 0; k < boundedCount; k++) {
                    if (honourTransparency && clear[k] || leftBy(k, scratch)) continue;
                    tests++;
                    if (blocks(k, honourTransparency && mayTransmit[k], ray, tMin, tMax, scratch)) {
                        if (!mayTransmit[k]) scratch.occluder = k;
                        return true;
                    }
                }
                return false;
            }
            if (boundedCount == 0) return false;
            ShadowBeam beam = scratch.activeBeam;
            if (beam != null
                    && honourTransparency
                    && tMin >= 0
                    && beam.covers(this, ray, tMax)
                    && beam.ready(bvh, scratch)) {
                return anyHitInBeam(beam, ray, tMin, tMax, scratch);
            }
            final float[] nodes = bvh.nodes;
            final WideBoxTest boxTest = WideBoxTest.SELECTED;
            final int[] stack = scratch.stack;
            final float[] entries = scratch.entries;
            final RaySlabs slabs = scratch.slabs;
            slabs.set(ray);
            final float tMinF = RaySlabs.below(tMin), tMaxF = RaySlabs.above(tMax);
            long visits = 1; // the root, as the statistics have always counted it
            int sp = 0;
            int link = bvh.rootLink, count = bvh.rootCount;
            // The root's slots of clear surfaces only, left out of a shadow query (the first node visited).
            int skip = honourTransparency ? bvh.secondGroupSlots : 0;
            boolean more = true; // no test of the root's own box, as in the closest-hit traversal
            try {
                while (more) {
                    if (count > 0 && CompiledPrimitives.isFilled(info[INFO * link + EDGES])) {
                        if (filledLeafBlocks(link, count, honourTransparency, ray, tMin, tMax, scratch)) return true;
                    } else if (count > 0) {
                        for (int k = link, end = link + count; k < end; k++) {
                            if (honourTransparency && clear[k] || leftBy(k, scratch)) continue;
                            tests++;
                            if (blocks(k, honourTransparency && mayTransmit[k], ray, tMin, tMax, scratch)) {
                                if (!mayTransmit[k]) scratch.occluder = k;
                                return true;
                            }
                        }
                    } else {
                        int o = BVH.nodeOffset(link);
                        visits += BVH.WIDTH;
                        // Any hit will do: no ordering, postpone every child hit but the first. (Taking the
                        // nearest first measured the same on the street's shadow rays, docs/BENCHMARKS.md.)
                        int mask = boxTest.test(nodes, o, slabs, tMinF, tMaxF, entries) & ~skip;
                        skip = 0;
                        if (mask != 0) {
                            int c = Integer.numberOfTrailingZeros(mask);
                            link = Float.floatToRawIntBits(nodes[o + BVH.LINK + c]);
                            count = Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
                            for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                                c = Integer.numberOfTrailingZeros(mask);
                                stack[2 * sp] = Float.floatToRawIntBits(nodes[o + BVH.LINK + c]);
                                stack[2 * sp++ + 1] = Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
                            }
                            continue;
                        }
                    }
                    more = sp > 0;
                    if (more) {
                        sp--;
                        link = stack[2 * sp];
                        count = stack[2 * sp + 1];
                    }
                }
                return false;
            } finally {
                scratch.nodeVisits += visits;
            }
        } finally {
            scratch.primitiveTests += tests;
        }
    }

    /**
     * Whether a triangle of the filled leaf of {@code count} at {@code link} (triangles of a large mesh only) blocks
     * the segment (then {@code scratch.occluder} names it if opaque); with {@code honourTransparency}, clear ones are
     * skipped and transparent ones collected. Adds its tests to the record. The filter's candidates are tested in the
     * leaf's lanes, the rest would be missed by their own test: skipping them changes nothing but the time. Its own
     * method, called from the traversal loops: written there, it made them too big for the JIT to inline a sphere's or
     * a plane's test in them (the street's shadow rays 0.93x).
     */
    private boolean filledLeafBlocks(
            int link, int count, boolean honourTransparency, Ray ray, double tMin, double tMax, HitRecord scratch) {
        int candidates = count > 1 ? leafFilter.candidates(triangles, 9 * link, count, ray) : 1;
        long tests = 0;
        try {
            for (int k = link, end = link + count; k < end; k++) {
                if (honourTransparency && clear[k] || leftBy(k, scratch)) continue;
                tests++;
                if ((candidates >> (k - link) & 1) == 0) continue;
                if (CompiledPrimitives.intersectFilled(
                                triangles, link, k - link, count, info[INFO * k + EDGES], ray, tMin, tMax, scratch)
                        && triangleBlocks(k, honourTransparency && mayTransmit[k], scratch)) {
                    if (!mayTransmit[k]) scratch.occluder = k;
                    return true;
                }
            }
            return false;
        } finally {
            scratch.primitiveTests += tests;
        }
    }

    /**
     * Whether bounded primitive {@code k} is (part of) the flat surface the query's segment leaves
     * ({@link HitRecord#leaveSurface}), which it cannot meet again.
     */
    private boolean leftBy(int k, HitRecord scratch) {
        Geometry surface = scratch.leaving;
        int r = INFO * k;
        return surface != null
                && info[r + EDGES] != OBJECT
                && geometries[info[r + OWNER]] == surface
                && (scratch.leavingPart < 0 || info[r + PART] == scratch.leavingPart);
    }

    /**
     * The occluder cache: whether the opaque primitive in slot {@code scratch.occluderHint} blocks the segment.
     * (Its own method, so that the traversal loop stays small enough for the JIT to inline the box test.)
     */
    private boolean blockedByHint(Ray ray, double tMin, double tMax, HitRecord scratch) {
        int hint = scratch.occluderHint;
        if (hint < 0 || hint >= boundedCount || mayTransmit[hint] || leftBy(hint, scratch)) return false;
        scratch.primitiveTests++;
        int edges = info[INFO * hint + EDGES];
        if (CompiledPrimitives.isFilled(edges)
                ? !filledTriangleHits(hint, edges, ray, tMin, tMax, scratch)
                : !blocks(hint, false, ray, tMin, tMax, scratch)) {
            return false;
        }
        scratch.occluder = hint;
        return true;
    }

    /**
     * Whether the segment hits triangle {@code k} of a filled leaf, whose {@link CompiledPrimitives#EDGES} entry is
     * {@code edges} (its lane and its leaf's count say where its coordinates are).
     */
    private boolean filledTriangleHits(int k, int edges, Ray ray, double tMin, double tMax, HitRecord scratch) {
        int lane = CompiledPrimitives.lane(edges);
        return CompiledPrimitives.intersectFilled(
                triangles, k - lane, lane, CompiledPrimitives.leafCount(edges), edges, ray, tMin, tMax, scratch);
    }

    /** Whether bounded primitive {@code k} blocks the segment; a transparent one is collected instead. */
    private boolean blocks(int k, boolean mayPass, Ray ray, double tMin, double tMax, HitRecord scratch) {
        int edges = info[INFO * k + EDGES];
        if (edges == OBJECT) return blocks(objects[k], info[INFO * k + INDEX], mayPass, ray, tMin, tMax, scratch);
        int o = 9 * k;
        return WatertightTriangle.intersect(triangles, o, o + 3, o + 6, edges, ray, tMin, tMax, scratch)
                && triangleBlocks(k, mayPass, scratch);
    }

    /** Whether triangle {@code k}, which the segment hits, blocks it; a transparent one is collected instead. */
    private boolean triangleBlocks(int k, boolean mayPass, HitRecord scratch) {
        if (!mayPass) return true;
        Double3 kT = geometries[info[INFO * k + OWNER]].getMaterial().getKt();
        if (kT.isZero()) return true;
        scratch.addTransparentHit(info[INFO * k + INDEX], kT.d1, kT.d2, kT.d3);
        return false;
    }

    /** Whether {@code object}, primitive {@code id}, blocks the segment; a transparent one is collected instead. */
    private static boolean blocks(
            Intersectable object, int id, boolean mayPass, Ray ray, double tMin, double tMax, HitRecord scratch) {
        if (!mayPass) return object.occludes(ray, tMin, tMax, scratch);
        if (object instanceof Instance instance) return instance.blocksLight(ray, tMin, tMax, scratch, id);
        // Every crossing of a transparent surface attenuates: walk all hits of this primitive in the segment.
        double from = tMin;
        while (object.intersect(ray, from, tMax, scratch)) {
            Double3 kT = scratch.geometry.getMaterial().getKt();
            if (kT.isZero()) return true;
            scratch.addTransparentHit(id, kT.d1, kT.d2, kT.d3);
            from = scratch.t;
        }
        return false;
    }
}
