package geometries;

import java.util.stream.IntStream;
import primitives.Double3;
import primitives.Ray;

/**
 * A scene's geometry compiled into flat arrays for the hot loop, searched with a {@link BVH} or, when the BVH is
 * switched off, by a linear scan over the very same arrays (brute force).
 *
 * <p>Compilation flattens nested {@link Geometries}, splits polygons into fan triangles and meshes into their
 * triangles (skipping those of zero area), and gathers every triangle's nine coordinates into one array in BVH
 * leaf order. Other bounded geometry (spheres, cylinders, user types) is called through {@link Intersectable};
 * unbounded geometry (planes, tubes) is tested beside the tree. Edges that lone triangles and polygons share
 * exactly are marked watertight.
 *
 * <p>Equal-distance hits are resolved toward the primitive added first, whatever the visiting order, so the BVH
 * and the brute-force scan return the same primitive and the same distance bit for bit.
 */
public final class Accelerator implements Intersectable {
    /** Default number of SAH bins per node. */
    public static final int DEFAULT_BINS = 16;
    /** Default maximum primitives per leaf. */
    public static final int DEFAULT_MAX_LEAF_SIZE = 4;

    private final int boundedCount;
    /** Per bounded primitive in search order: 9 coordinates if it is a triangle. */
    private final double[] triangles;

    /**
     * Two ints per primitive, read together by every test: the original (insertion) index, which is the
     * deterministic tie-break, then a triangle's shared-edge flags or {@link #OBJECT} for other shapes.
     */
    private final int[] info;
    /** The geometry owning each triangle and the part index within it; read once per query, for the final hit. */
    private final Geometry[] owners;

    private final int[] parts;
    /** Non-triangle bounded primitives (null where the primitive is a triangle). */
    private final Intersectable[] objects;
    /** Whether a primitive may let light through (then shadow rays must look past it). */
    private final boolean[] mayTransmit;
    /**
     * Whether a primitive is clear (a Geometry whose kT is exactly 1 in every channel): it changes no transmittance
     * (a product times 1 is exact), so shadow queries skip it; the lamp globes of the street are such.
     */
    private final boolean[] clear;

    private final Intersectable[] unbounded;
    private final boolean[] unboundedMayTransmit, unboundedClear;
    /** The distinct prototypes of the instances among the primitives, each stored once. */
    private final Prototype[] prototypes;

    private final BVH bvh;
    private final double buildSeconds;
    /** Build phases in seconds: gathering primitives, primitive boxes, the BVH proper, laying out the arrays. */
    private final double collectSeconds, boxSeconds, bvhSeconds, layoutSeconds;

    private Accelerator(PrimitiveCollector c, boolean useBvh, int bins, int maxLeafSize, long collectStart) {
        long start = System.nanoTime();
        collectSeconds = (start - collectStart) * 1e-9;
        c.markSharedOutlineEdges();
        int n = c.count;
        boundedCount = n;
        double[] boxes = useBvh && n > 0 ? c.boxes() : null;
        long boxesDone = System.nanoTime();
        // Clear surfaces get a subtree of their own under the root, which shadow queries leave out.
        bvh = boxes != null ? BVH.build(boxes, bins, maxLeafSize, c.clear) : null;
        long bvhDone = System.nanoTime();
        boxSeconds = (boxesDone - start) * 1e-9;
        bvhSeconds = (bvhDone - boxesDone) * 1e-9;
        triangles = new double[9 * n];
        info = new int[2 * n];
        owners = new Geometry[n];
        parts = new int[n];
        objects = new Intersectable[n];
        mayTransmit = new boolean[n];
        clear = new boolean[n];
        // Each position is written from its own primitive alone, so large meshes lay out on all cores.
        IntStream positions = IntStream.range(0, n);
        (n >= PARALLEL_LAYOUT ? positions.parallel() : positions).forEach(k -> layOut(c, k));
        java.util.Set<Prototype> placed = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        for (Intersectable object : objects) if (object instanceof Instance instance) placed.add(instance.prototype());
        prototypes = placed.toArray(new Prototype[0]);
        unbounded = c.unbounded.toArray(new Intersectable[0]);
        unboundedMayTransmit = new boolean[unbounded.length];
        unboundedClear = new boolean[unbounded.length];
        for (int j = 0; j < unbounded.length; j++) {
            unboundedMayTransmit[j] = mayTransmit(unbounded[j]);
            unboundedClear[j] = isClear(unbounded[j]);
        }
        long end = System.nanoTime();
        layoutSeconds = (end - bvhDone) * 1e-9;
        buildSeconds = (end - collectStart) * 1e-9;
    }

    /** Primitives from which the layout runs in parallel. */
    private static final int PARALLEL_LAYOUT = 1 << 16;

    /** Writes the primitive at position {@code k} of the leaf order into the flat arrays. */
    private void layOut(PrimitiveCollector c, int k) {
        int i = bvh == null ? k : bvh.order[k];
        info[2 * k] = i;
        objects[k] = c.objects[i];
        mayTransmit[k] = c.mayTransmit[i];
        clear[k] = c.clear[i];
        if (objects[k] == null) {
            System.arraycopy(c.triangles, 9 * i, triangles, 9 * k, 9);
            info[2 * k + 1] = c.shared[i];
            owners[k] = c.owners[i];
            parts[k] = c.parts[i];
        } else {
            info[2 * k + 1] = OBJECT;
        }
    }

    /**
     * Compiles {@code geometry} with a BVH of default settings, or for brute-force search.
     *
     * @param geometry the scene or geometry to compile; not null
     * @param useBvh true to build a BVH, false to test every primitive (brute force)
     * @return the compiled search structure
     */
    public static Accelerator build(Intersectable geometry, boolean useBvh) {
        return build(geometry, useBvh, DEFAULT_BINS, DEFAULT_MAX_LEAF_SIZE);
    }

    /**
     * Compiles {@code geometry}; {@code bins} and {@code maxLeafSize} tune the BVH build.
     *
     * @param geometry the scene or geometry to compile; not null
     * @param useBvh true to build a BVH, false to test every primitive (brute force)
     * @param bins the number of SAH bins per node, 2..256 (checked even without a BVH)
     * @param maxLeafSize the most primitives a leaf may hold, 1..64 (checked even without a BVH)
     * @return the compiled search structure
     * @throws IllegalArgumentException if {@code geometry} is null or a BVH setting is out of range
     */
    public static Accelerator build(Intersectable geometry, boolean useBvh, int bins, int maxLeafSize) {
        primitives.Util.requireNonNull(geometry, "geometry");
        // Checked here, not only in BVH.build, so bad settings fail the same way for empty and brute-force scenes.
        BVH.validateSettings(bins, maxLeafSize);
        long start = System.nanoTime();
        PrimitiveCollector c = new PrimitiveCollector();
        c.collect(geometry);
        return new Accelerator(c, useBvh, bins, maxLeafSize, start);
    }

    /**
     * The BVH, or null in brute-force mode or for a scene without bounded geometry.
     *
     * @return the BVH, or null
     */
    public BVH getBvh() {
        return bvh;
    }

    /**
     * Bounded primitives (triangles and other bounded shapes) in the search structure.
     *
     * @return the number of bounded primitives
     */
    public int boundedPrimitiveCount() {
        return boundedCount;
    }

    /**
     * Primitives tested beside the tree.
     *
     * @return the number of unbounded primitives (planes, tubes)
     */
    public int unboundedPrimitiveCount() {
        return unbounded.length;
    }

    /**
     * Wall time of compilation including the BVH build, in seconds.
     *
     * @return the build time in seconds
     */
    public double buildSeconds() {
        return buildSeconds;
    }

    /**
     * Where the build time went, phase by phase, for benchmark reports.
     *
     * @return the seconds of collection, boxes, BVH build and layout, as one line
     */
    public String buildBreakdown() {
        return String.format(
                java.util.Locale.ROOT,
                "collect %.3f s, boxes %.3f s, BVH %.3f s, layout %.3f s",
                collectSeconds,
                boxSeconds,
                bvhSeconds,
                layoutSeconds);
    }

    /**
     * Bytes of the flat primitive arrays plus the BVH, and those of each prototype placed by an instance (once,
     * however many instances place it).
     *
     * @return the size in bytes of the search structure's arrays
     */
    public long bytes() {
        long b = 8L * triangles.length
                + 4L * (info.length + parts.length)
                + 8L * (owners.length + objects.length)
                + 2L * mayTransmit.length;
        for (Prototype p : prototypes) b += p.bytes();
        return b + (bvh == null ? 0 : bvh.bytes());
    }

    /**
     * Primitives stored: the bounded primitives here (an instance counts as one) plus those of every distinct
     * prototype, once each.
     *
     * @return the number of primitives held in memory
     */
    public long storedPrimitiveCount() {
        long n = boundedCount;
        for (Prototype p : prototypes) n += p.primitiveCount();
        return n;
    }

    /**
     * Primitives the scene shows: as {@link #storedPrimitiveCount()}, but counting a prototype's primitives once per
     * instance (what copying the geometry would store).
     *
     * @return the number of primitives the instances and the rest place in the scene
     */
    public long placedPrimitiveCount() {
        long n = boundedCount;
        for (Intersectable object : objects) {
            if (object instanceof Instance instance) n += instance.prototype().primitiveCount() - 1;
        }
        return n;
    }

    @Override
    public BoundingBox getBoundingBox() {
        if (unbounded.length > 0 || boundedCount == 0) return null;
        if (bvh != null) return bvh.bounds();
        throw new UnsupportedOperationException("bounds of a brute-force accelerator are not tracked");
    }

    // ---------------------------------------------------------------- closest hit

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
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
        if (bvh == null) {
            for (int k = 0; k < boundedCount; k++) {
                tests++;
                if (testPrimitive(k, ray, tMin, info[2 * k] < best ? tieLimit : tMax, hit)) {
                    tMax = hit.t;
                    tieLimit = Math.nextUp(tMax);
                    best = info[2 * k];
                    bestTriangle = info[2 * k + 1] == OBJECT ? -1 : k;
                    bestObject = info[2 * k + 1] == OBJECT ? k : -1;
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
                if (count > 0) {
                    for (int k = link, end = link + count; k < end; k++) {
                        tests++;
                        if (testPrimitive(k, ray, tMin, info[2 * k] < best ? tieLimit : tMax, hit)) {
                            tMax = hit.t;
                            tMaxF = RaySlabs.above(tMax);
                            tieLimit = Math.nextUp(tMax);
                            best = info[2 * k];
                            bestTriangle = info[2 * k + 1] == OBJECT ? -1 : k;
                            bestObject = info[2 * k + 1] == OBJECT ? k : -1;
                        }
                    }
                } else {
                    // All children's boxes come with this node: test them, go to the nearest, postpone the others.
                    int o = BVH.NODE_STRIDE * link;
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
            hit.geometry = owners[bestTriangle];
            hit.part = parts[bestTriangle];
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
        int edges = info[2 * k + 1];
        if (edges == OBJECT) return objects[k].intersect(ray, tMin, tMax, hit);
        int o = 9 * k;
        return WatertightTriangle.intersect(triangles, o, o + 3, o + 6, edges, ray, tMin, tMax, hit);
    }

    /** The shared-edge entry of {@link #info} for a primitive that is not a triangle. */
    private static final int OBJECT = -1;

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

    // ---------------------------------------------------------------- shadows

    @Override
    public boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        return anyHit(ray, tMin, tMax, scratch, false);
    }

    /**
     * The fraction of light that passes along the ray through {@code (tMin, tMax)}: {@link Double3#ONE} when
     * nothing is in the way, {@link Double3#ZERO} when an opaque surface is, otherwise the product of the
     * transparency kT of every surface crossed. A convenience over {@link #passesLight}, which the renderer calls
     * without allocating.
     *
     * @param ray the shadow ray
     * @param tMin the start of the searched interval, exclusive
     * @param tMax the end of the searched interval, exclusive (the distance to the light)
     * @param scratch a record the search may overwrite
     * @return the transmittance per channel, each in [0, 1]
     */
    public Double3 transmittance(Ray ray, double tMin, double tMax, HitRecord scratch) {
        if (!passesLight(ray, tMin, tMax, scratch)) return Double3.ZERO;
        if (scratch.transmitR == 1 && scratch.transmitG == 1 && scratch.transmitB == 1) return Double3.ONE;
        return new Double3(scratch.transmitR, scratch.transmitG, scratch.transmitB);
    }

    /**
     * The shadow query: whether light passes along the ray through {@code (tMin, tMax)}. False when an opaque
     * surface is in the way (the search stops there); otherwise true, with the product of the transparency kT of
     * every surface crossed in {@link HitRecord#transmitR}, {@code transmitG}, {@code transmitB} (exactly 1 when
     * nothing is in the way). The factors are multiplied in primitive order, so the result does not depend on the
     * visiting order; one or two factors need no ordering (a product of two doubles commutes exactly).
     *
     * <p>The occluder cache: the bounded primitive in slot {@link HitRecord#occluderHint} (when non-negative) is
     * tested before the search, and the slot of the opaque primitive that blocked is left in
     * {@link HitRecord#occluder} (-1 when none, or when the blocker was unbounded or may let light through). Callers
     * keep the last occluder per light: neighbouring shadow rays toward a light are usually blocked by the same
     * primitive. The answer is the same with any hint.
     *
     * @param ray the shadow ray
     * @param tMin the start of the searched interval, exclusive
     * @param tMax the end of the searched interval, exclusive (the distance to the light)
     * @param scratch the record receiving the transmittance and the occluder, holding the occluder hint
     * @return true when no opaque surface blocks the light
     */
    public boolean passesLight(Ray ray, double tMin, double tMax, HitRecord scratch) {
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
     * Announces a beam of shadow queries through {@code scratch}: segments that start within {@code radius} (per
     * axis) of (px, py, pz) and end within {@code radius} of (cx, cy, cz), such as the rays from shading points toward
     * a disk light. The tree is then searched once for the beam, and every {@link #passesLight} query whose segment
     * lies within it tests only the leaves found. The answers are the same as without the beam, bit for bit: a query
     * the beam does not cover searches the tree as usual. Scenes of fewer than {@value ShadowBeam#MIN_PRIMITIVES}
     * bounded primitives, and brute-force search, have no beams.
     *
     * <p>A record keeps a few beams per {@code slot} (a light's index, say): aiming again toward the same end from a
     * start within 0.9 of the radius of one of them keeps what that one found, so neighbouring shading points share
     * one search. Aiming makes that beam the one later queries use.
     *
     * @param scratch the record the queries will use
     * @param slot the beam's slot in the record, at least 0 (one per light, say)
     * @param px the x coordinate the segments start near
     * @param py the y coordinate the segments start near
     * @param pz the z coordinate the segments start near
     * @param cx the x coordinate of the centre the segments end near
     * @param cy the y coordinate of the centre the segments end near
     * @param cz the z coordinate of the centre the segments end near
     * @param radius how far, per axis, a segment's start and end may lie from the beam's
     * @throws IllegalArgumentException if {@code slot} is negative
     */
    public void aimShadowBeam(
            HitRecord scratch,
            int slot,
            double px,
            double py,
            double pz,
            double cx,
            double cy,
            double cz,
            double radius) {
        if (slot < 0) throw new IllegalArgumentException("beam slot must be at least 0, but was " + slot);
        // Brute force, or a tree too small for a search to cost more than a beam's own set-up: nothing to share.
        if (bvh == null || boundedCount < ShadowBeam.MIN_PRIMITIVES) return;
        scratch.aimShadowBeam(slot, this, px, py, pz, cx, cy, cz, radius);
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
                    int end = link + Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
                    for (int k = link; k < end; k++) {
                        if (clear[k]) continue;
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
                if (honourTransparency && unboundedClear[j]) continue;
                tests++;
                boolean pass = honourTransparency && unboundedMayTransmit[j];
                if (blocks(unbounded[j], boundedCount + j, pass, ray, tMin, tMax, scratch)) return true;
            }
            if (bvh == null) {
                for (int k = 0; k < boundedCount; k++) {
                    if (honourTransparency && clear[k]) continue;
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
            boolean more = true; // no test of the root's own box, as in intersect
            try {
                while (more) {
                    if (count > 0) {
                        for (int k = link, end = link + count; k < end; k++) {
                            if (honourTransparency && clear[k]) continue;
                            tests++;
                            if (blocks(k, honourTransparency && mayTransmit[k], ray, tMin, tMax, scratch)) {
                                if (!mayTransmit[k]) scratch.occluder = k;
                                return true;
                            }
                        }
                    } else {
                        int o = BVH.NODE_STRIDE * link;
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
     * The occluder cache: whether the opaque primitive in slot {@code scratch.occluderHint} blocks the segment.
     * (Its own method, so that the traversal loop stays small enough for the JIT to inline the box test.)
     */
    private boolean blockedByHint(Ray ray, double tMin, double tMax, HitRecord scratch) {
        int hint = scratch.occluderHint;
        if (hint < 0 || hint >= boundedCount || mayTransmit[hint]) return false;
        scratch.primitiveTests++;
        if (!blocks(hint, false, ray, tMin, tMax, scratch)) return false;
        scratch.occluder = hint;
        return true;
    }

    /** Whether bounded primitive {@code k} blocks the segment; a transparent one is collected instead. */
    private boolean blocks(int k, boolean mayPass, Ray ray, double tMin, double tMax, HitRecord scratch) {
        int edges = info[2 * k + 1];
        if (edges == OBJECT) return blocks(objects[k], info[2 * k], mayPass, ray, tMin, tMax, scratch);
        int o = 9 * k;
        if (!WatertightTriangle.intersect(triangles, o, o + 3, o + 6, edges, ray, tMin, tMax, scratch)) {
            return false;
        }
        if (!mayPass) return true;
        Double3 kT = owners[k].getMaterial().getKt();
        if (kT.isZero()) return true;
        scratch.addTransparentHit(info[2 * k], kT.d1, kT.d2, kT.d3);
        return false;
    }

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

    static boolean isClear(Intersectable g) {
        if (!(g instanceof Geometry geometry)) return false;
        Double3 kT = geometry.getMaterial().getKt();
        return kT.d1 == 1 && kT.d2 == 1 && kT.d3 == 1;
    }

    /** Whether any primitive may let light through. */
    boolean mayTransmit() {
        for (boolean b : mayTransmit) if (b) return true;
        for (boolean b : unboundedMayTransmit) if (b) return true;
        return false;
    }

    static boolean mayTransmit(Intersectable g) {
        if (g instanceof Instance instance) return instance.mayTransmit();
        // Non-Geometry members (user composites) may contain transparent surfaces: decide per hit.
        return !(g instanceof Geometry geometry) || geometry.getMaterial().isTransparent();
    }
}
