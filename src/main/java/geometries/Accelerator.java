package geometries;

import primitives.Double3;
import primitives.Ray;
import primitives.Util;

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
 *
 * <p>This class builds the search structure and answers for it; the arrays, the closest-hit traversal and the
 * shadow queries are package-private classes of their own (CompiledPrimitives, ClosestHitTraversal, ShadowQueries).
 */
public final class Accelerator implements Intersectable {
    /** Default number of SAH bins per node. */
    public static final int DEFAULT_BINS = 16;
    /** Default maximum primitives per leaf. */
    public static final int DEFAULT_MAX_LEAF_SIZE = 4;

    /** The primitives laid out flat in leaf order, which both searches read. */
    private final CompiledPrimitives primitives;

    /** The BVH, or null in brute-force mode or for a scene without bounded geometry. */
    private final BVH bvh;
    /** The closest-hit search over the primitives and the tree. */
    private final ClosestHitTraversal closestHit;
    /** The shadow (any-hit) queries, over the same primitives and tree. */
    private final ShadowQueries shadows;
    /** The distinct prototypes of the instances among the primitives, each stored once. */
    private final Prototype[] prototypes;

    private final double buildSeconds;
    /** Build phases in seconds: gathering primitives, primitive boxes, the BVH proper, laying out the arrays. */
    private final double collectSeconds, boxSeconds, bvhSeconds, layoutSeconds;

    private Accelerator(PrimitiveCollector c, boolean useBvh, int bins, int maxLeafSize, long collectStart) {
        long start = System.nanoTime();
        collectSeconds = (start - collectStart) * 1e-9;
        c.markSharedOutlineEdges();
        int n = c.count;
        float[] boxes = useBvh && n > 0 ? c.boxes() : null;
        long boxesDone = System.nanoTime();
        // Clear surfaces get a subtree of their own under the root, which shadow queries leave out.
        FilledLeaves filled = boxes != null ? filledLeaves(c) : FilledLeaves.NONE;
        bvh = boxes != null ? BVH.build(boxes, bins, maxLeafSize, filled, c.clear) : null;
        long bvhDone = System.nanoTime();
        boxSeconds = (boxesDone - start) * 1e-9;
        bvhSeconds = (bvhDone - boxesDone) * 1e-9;
        primitives = new CompiledPrimitives(c, bvh, filled);
        java.util.Set<Prototype> placed = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        for (Intersectable object : primitives.objects) {
            if (object instanceof Instance instance) placed.add(instance.prototype());
        }
        prototypes = placed.toArray(new Prototype[0]);
        closestHit = new ClosestHitTraversal(primitives, bvh);
        shadows = new ShadowQueries(primitives, bvh);
        long end = System.nanoTime();
        layoutSeconds = (end - bvhDone) * 1e-9;
        buildSeconds = (end - collectStart) * 1e-9;
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
        Util.requireNonNull(geometry, "geometry");
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

    /** The flat arrays both searches read (for the kernel's C twin, which exports them). */
    CompiledPrimitives compiledPrimitives() {
        return primitives;
    }

    /** Whether some leaves are filled and tested by the {@link LeafFilter}: there is a filter and a large mesh. */
    boolean filtersLeaves() {
        return primitives.filtersLeaves;
    }

    /**
     * Which primitives the {@link LeafFilter} takes, in leaves it fills: the triangles of meshes of at least {@link
     * LeafFilter#MIN_MESH} triangles; none without a filter.
     */
    private static FilledLeaves filledLeaves(PrimitiveCollector c) {
        Geometry[] owners = c.ownerTable();
        boolean[] large = new boolean[owners.length];
        boolean anyLarge = false;
        for (int s = 0; s < owners.length; s++) {
            large[s] = owners[s] instanceof Mesh mesh && mesh.triangleCount() >= LeafFilter.MIN_MESH;
            anyLarge |= large[s];
        }
        // The filter is asked for only now: its class loads the Vector API, which a scene of small meshes and
        // shapes need not wait for (MIN_MESH is a constant, read without loading the class).
        if (!anyLarge || LeafFilter.SELECTED == null) return FilledLeaves.NONE;
        boolean[] filterable = new boolean[c.count];
        boolean all = true;
        for (int i = 0; i < c.count; i++) {
            filterable[i] = c.objects[i] == null && large[c.owners[i]];
            all &= filterable[i];
        }
        return new FilledLeaves(LeafFilter.LANES, all ? null : filterable);
    }

    /**
     * Bounded primitives (triangles and other bounded shapes) in the search structure.
     *
     * @return the number of bounded primitives
     */
    public int boundedPrimitiveCount() {
        return primitives.boundedCount;
    }

    /**
     * Primitives tested beside the tree.
     *
     * @return the number of unbounded primitives (planes, tubes)
     */
    public int unboundedPrimitiveCount() {
        return primitives.unbounded.length;
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
        long b = primitives.bytes();
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
        long n = primitives.boundedCount;
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
        long n = primitives.boundedCount;
        for (Intersectable object : primitives.objects) {
            if (object instanceof Instance instance) n += instance.prototype().primitiveCount() - 1;
        }
        return n;
    }

    @Override
    public BoundingBox getBoundingBox() {
        if (primitives.unbounded.length > 0 || primitives.boundedCount == 0) return null;
        if (bvh != null) return bvh.bounds();
        throw new UnsupportedOperationException("bounds of a brute-force accelerator are not tracked");
    }

    // ---------------------------------------------------------------- queries

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        return closestHit.intersect(ray, tMin, tMax, hit);
    }

    @Override
    public boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        return shadows.occludes(ray, tMin, tMax, scratch);
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
        return shadows.passesLight(ray, tMin, tMax, scratch);
    }

    /**
     * Whether {@link #blockShadowPacket} applies: no tree to search (brute force, or one bounded primitive), every
     * bounded primitive a whole object (no mesh triangles), and nothing that may let light through.
     *
     * @return true when packets of shadow segments may be tested here
     */
    public boolean testsShadowPackets() {
        return shadows.testsPackets;
    }

    /**
     * The shadow query for a packet of segments at once (where {@link #testsShadowPackets}): marks each segment an
     * opaque surface blocks. The answers are those of {@link #passesLight} over each segment's interval
     * {@code (0, tMax)}, bit for bit, with the surface {@code scratch} leaves ({@link HitRecord#leaveSurface}) left
     * out as there; the occluder cache is neither read nor written.
     *
     * @param packet the segments
     * @param scratch a record the queries may overwrite, holding the surface the segments leave
     * @throws IllegalStateException if packets do not apply to this accelerator
     */
    public void blockShadowPacket(ShadowPacket packet, HitRecord scratch) {
        if (!shadows.testsPackets) {
            throw new IllegalStateException(
                    "shadow packets need brute-force search or a single bounded primitive, whole objects only, "
                            + "and no transparent surfaces; test the segments with passesLight instead");
        }
        shadows.blockPacket(packet, scratch);
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
        if (bvh == null || primitives.boundedCount < ShadowBeam.MIN_PRIMITIVES) return;
        scratch.aimShadowBeam(slot, shadows, px, py, pz, cx, cy, cz, radius);
    }

    /** Whether any primitive may let light through. */
    boolean mayTransmit() {
        return primitives.mayTransmit();
    }
}
