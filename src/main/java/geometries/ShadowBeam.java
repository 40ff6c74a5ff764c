package geometries;

import primitives.Ray;
import primitives.ReusableRay;

/**
 * The leaves of a BVH that a beam of shadow rays can meet: rays from about one place toward a disk (a soft light
 * seen from neighbouring shading points) share their path through the tree, so the tree is searched once for the
 * whole beam, with a "fat" ray whose boxes are widened by the beam's radius, and every ray of the beam then tests
 * only the leaves found, eight leaf boxes per vector operation, as if they were the children of one node.
 *
 * <p>Exactness: a point of any covered ray's segment lies within the radius (per axis) of the beam's central
 * segment, so a leaf box such a ray enters is entered by the central segment once widened by the radius, and the
 * fat search, conservative like every box test here (docs/ROBUSTNESS.md), finds that leaf. A ray therefore tests
 * every primitive its own traversal would test, and perhaps a few more: its answer is the same bit for bit (any-hit
 * answers and transmittance products do not depend on the order of the tests). Which rays a beam covers is checked
 * per ray ({@link #covers}), so a caller's mistake costs speed, never a wrong answer.
 *
 * <p>A beam is aimed with {@link Accelerator#aimShadowBeam}; the search runs on the first ray that needs it and is
 * kept while the beam serves the same light from nearby. Beams live in a {@link HitRecord} (a few per light, since
 * consecutive shading points may alternate between distant surfaces), so per thread.
 */
final class ShadowBeam {
    /** The most leaves a beam holds; a search that finds more gives up, and the rays search the tree one by one. */
    static final int MAX_LEAVES = 8 * BVH.WIDTH;
    /**
     * The fewest bounded primitives for which beams are aimed: below, a ray's own search is about as cheap as testing
     * a beam's leaves (POV-Ray's soft-shadow scene, one sphere in the tree, measured slower with beams).
     */
    static final int MIN_PRIMITIVES = 64;
    /** How far a central segment along an axis is tilted, relative to the radius and to its length. */
    private static final double TILT = 0x1p-10;
    /** Relative widening of the radius and the length, for the rounding of the fat ray's constants. */
    private static final double RELATIVE_MARGIN = 0x1p-20;

    private enum State {
        /** Not aimed. */
        OFF,
        /** Aimed, the tree not yet searched. */
        AIMED,
        /** The leaves are in {@link #leafNodes}. */
        COLLECTED,
        /**
         * Aimed, but of no use: too many leaves, or a fat ray the float test cannot hold. Kept like a collected beam
         * (a nearby start would find the same), while its rays search the tree one by one.
         */
        FULL
    }

    private State state = State.OFF;
    /** The shadow queries (one accelerator's) the beam was aimed for; it is only used with the tree it searched. */
    private ShadowQueries owner;
    /** The central segment: from (px, py, pz) to (cx, cy, cz), and the beam's radius around it (per axis). */
    private double px, py, pz, cx, cy, cz, radius;
    /** The leaves found, in groups of {@link BVH#WIDTH} laid out as BVH nodes (boxes, links, counts). */
    final float[] leafNodes = new float[MAX_LEAVES / BVH.WIDTH * BVH.NODE_STRIDE];
    /** How many groups of {@link #leafNodes} hold leaves. */
    int groups;

    private int leaves;
    private final ReusableRay central = new ReusableRay();
    private final RaySlabs fat = new RaySlabs();

    /**
     * Whether this beam serves segments from near (px, py, pz) toward the same centre with the same radius in the
     * same tree: its start lies within 0.9 of the radius of the new one, so a segment from near the new start still
     * lies within the beam (checked per ray by {@link #covers}).
     */
    boolean serves(ShadowQueries queries, double px, double py, double pz, double cx, double cy, double cz, double r) {
        double keep = 0.9 * r;
        return state != State.OFF
                && owner == queries
                && cx == this.cx
                && cy == this.cy
                && cz == this.cz
                && r == radius
                && Math.abs(px - this.px) <= keep
                && Math.abs(py - this.py) <= keep
                && Math.abs(pz - this.pz) <= keep;
    }

    /** Aims the beam at segments from within {@code r} of (px, py, pz) to within {@code r} of (cx, cy, cz). */
    void aim(ShadowQueries queries, double px, double py, double pz, double cx, double cy, double cz, double r) {
        boolean usable = r > 0 && r < Double.POSITIVE_INFINITY && (cx != px || cy != py || cz != pz);
        state = usable ? State.AIMED : State.FULL;
        owner = queries;
        this.px = px;
        this.py = py;
        this.pz = pz;
        this.cx = cx;
        this.cy = cy;
        this.cz = cz;
        radius = r;
    }

    /**
     * Whether the segment of {@code ray} through (0, tMax) lies within the beam: its origin within the radius of the
     * central segment's start and its end within the radius of the central segment's end, per axis. Then every
     * point of it lies within the radius of the central segment.
     */
    boolean covers(ShadowQueries queries, Ray ray, double tMax) {
        if (!(state == State.COLLECTED || state == State.AIMED) || owner != queries) return false;
        if (!(tMax < Double.POSITIVE_INFINITY)) return false;
        double ox = ray.ox(), oy = ray.oy(), oz = ray.oz();
        double ex = ox + ray.dx() * tMax, ey = oy + ray.dy() * tMax, ez = oz + ray.dz() * tMax;
        double r = radius;
        return Math.abs(ox - px) <= r
                && Math.abs(oy - py) <= r
                && Math.abs(oz - pz) <= r
                && Math.abs(ex - cx) <= r
                && Math.abs(ey - cy) <= r
                && Math.abs(ez - cz) <= r;
    }

    /**
     * Whether the leaves are found, searching the tree first if this is the first ray that needs them (leaving out
     * the root's slots of clear surfaces, as shadow queries do; the search's node visits count in the record).
     */
    boolean ready(BVH bvh, HitRecord scratch) {
        if (state == State.AIMED) collect(bvh, scratch);
        return state == State.COLLECTED;
    }

    /** Whether the leaves are found (for tests). */
    boolean collected() {
        return state == State.COLLECTED;
    }

    /**
     * Searches the tree with the fat central ray: its slab constants moved by the radius, which widens every box
     * by the radius on each side. The radius and the length are widened a little more for the rounding of those
     * constants and of the beam's own coordinates (the covered rays' ends are computed in double).
     */
    private void collect(BVH bvh, HitRecord scratch) {
        state = State.FULL;
        leaves = 0;
        double dx = cx - px, dy = cy - py, dz = cz - pz;
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double scale = Math.max(Math.abs(px), Math.max(Math.abs(py), Math.abs(pz)))
                + Math.max(Math.abs(cx), Math.max(Math.abs(cy), Math.abs(cz)))
                + length;
        double r = radius * (1 + RELATIVE_MARGIN) + scale * RELATIVE_MARGIN;
        // A central segment (nearly) along an axis has no float reciprocal there: tilt its end by a small part of the
        // radius on such axes and widen by as much, which keeps every covered ray inside.
        double tilt = radius * TILT, axial = length * TILT;
        boolean tilted = false;
        if (!(Math.abs(dx) > axial)) {
            dx += tilt;
            tilted = true;
        }
        if (!(Math.abs(dy) > axial)) {
            dy += tilt;
            tilted = true;
        }
        if (!(Math.abs(dz) > axial)) {
            dz += tilt;
            tilted = true;
        }
        if (tilted) {
            r += 2 * tilt;
            length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        }
        central.set(px, py, pz, dx, dy, dz);
        fat.set(central);
        if (!fat.widen(r)) return;
        float tMinF = RaySlabs.below(-r), tMaxF = RaySlabs.above(length * (1 + RELATIVE_MARGIN) + r);
        if (bvh.rootCount > 0) {
            if (!addLeaf(bvh.rootBounds, 0, 1, bvh.rootLink, bvh.rootCount)) return;
        } else {
            float[] nodes = bvh.nodes;
            WideBoxTest boxTest = WideBoxTest.SELECTED;
            int[] stack = scratch.stack;
            float[] entries = scratch.entries;
            int skip = bvh.secondGroupSlots;
            int sp = 0;
            int link = bvh.rootLink;
            while (true) {
                int o = BVH.nodeOffset(link);
                scratch.nodeVisits += BVH.WIDTH;
                int mask = boxTest.test(nodes, o, fat, tMinF, tMaxF, entries) & ~skip;
                skip = 0;
                for (; mask != 0; mask &= mask - 1) {
                    int c = Integer.numberOfTrailingZeros(mask);
                    int childLink = Float.floatToRawIntBits(nodes[o + BVH.LINK + c]);
                    int childCount = Float.floatToRawIntBits(nodes[o + BVH.COUNT + c]);
                    if (childCount > 0) {
                        if (!addLeaf(nodes, o + c, BVH.WIDTH, childLink, childCount)) return;
                    } else {
                        stack[sp++] = childLink;
                    }
                }
                if (sp == 0) break;
                link = stack[--sp];
            }
        }
        groups = (leaves + BVH.WIDTH - 1) / BVH.WIDTH;
        // The rest of the last group: empty boxes, which every ray misses.
        for (int slot = leaves; slot < groups * BVH.WIDTH; slot++) {
            int o = slot / BVH.WIDTH * BVH.NODE_STRIDE + slot % BVH.WIDTH;
            for (int axis = 0; axis < 3; axis++) {
                leafNodes[o + BVH.MIN_X + axis * BVH.WIDTH] = Float.POSITIVE_INFINITY;
                leafNodes[o + BVH.MAX_X + axis * BVH.WIDTH] = Float.NEGATIVE_INFINITY;
            }
            leafNodes[o + BVH.LINK] = 0;
            leafNodes[o + BVH.COUNT] = 0;
        }
        state = State.COLLECTED;
    }

    /**
     * Appends a leaf whose box is read from {@code boxes} at {@code o} with the coordinates {@code stride} apart (a
     * node's child slot, or the root's bounds); false when the beam is full.
     */
    private boolean addLeaf(float[] boxes, int o, int stride, int link, int count) {
        if (leaves == MAX_LEAVES) return false;
        int d = leaves / BVH.WIDTH * BVH.NODE_STRIDE + leaves % BVH.WIDTH;
        for (int k = 0; k < 6; k++) leafNodes[d + k * BVH.WIDTH] = boxes[o + k * stride];
        leafNodes[d + BVH.LINK] = Float.intBitsToFloat(link);
        leafNodes[d + BVH.COUNT] = Float.intBitsToFloat(count);
        leaves++;
        return true;
    }
}
