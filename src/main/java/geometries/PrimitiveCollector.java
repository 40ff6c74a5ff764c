package geometries;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * Gathers the primitives of a geometry tree for {@link Accelerator}: triangles of polygons (fans) and meshes, each
 * known by its owner and part (its vertices are read from there, not copied: {@link #copyTriangle}), other bounded
 * shapes as objects, unbounded ones apart, and the outline edges that lone triangles and polygons share exactly (made
 * watertight). Per-primitive arrays grow by doubling, since a million-triangle mesh passes through here.
 */
final class PrimitiveCollector {
    /**
     * Slack on primitive boxes, relative to the box's largest magnitude, so that rounding in the kernels never reports
     * a hit just outside a box. The padded bounds are then rounded to the nearest float, which moves them by at most
     * half a float step (2^-24 of the magnitude, or 2^-150 near zero): a pad of 2^-23 plus 2^-148 leaves at least 2^-24
     * outside the box, far more than the kernels need. The nearest float costs no branch; rounding outward exactly
     * (one in two values a step further) made the boxes of the 1M heightfield about 3x slower (best of 25:
     * 0.018-0.020 s against 0.006 s).
     */
    private static final double BOX_PAD = 0x1p-23;

    int count;
    int[] shared = new int[64];
    int[] parts = new int[64];
    /** Each triangle's owner, as its slot in {@link #ownerTable()}. */
    int[] owners = new int[64];
    // Plain arrays grown by doubling, like the ones above: a million-triangle mesh passes through here.
    Intersectable[] objects = new Intersectable[64];
    boolean[] mayTransmit = new boolean[64];
    boolean[] clear = new boolean[64];
    BoundingBox[] objectBoxes = new BoundingBox[64];
    final List<Intersectable> unbounded = new ArrayList<>();
    /**
     * The geometries that own triangles, each once, in the order first met: the first {@link #ownerCount} slots, read
     * on all cores by {@link #copyTriangle} and {@link #boxes}.
     */
    private Geometry[] ownerTable = new Geometry[8];

    private int ownerCount;

    private final Map<Geometry, Integer> ownerSlots = new IdentityHashMap<>();
    /** Outline edges of lone triangles and polygons: edge key to (primitive, edge flag) pairs. */
    final Map<EdgeKey, List<int[]>> outlineEdges = new HashMap<>();

    void collect(Intersectable g) {
        if (g instanceof Geometries composite) {
            for (Intersectable member : composite.getMembers()) collect(member);
        } else if (g instanceof Polygon polygon) {
            collectPolygon(polygon);
        } else if (g instanceof Mesh mesh) {
            collectMesh(mesh);
        } else if (g.getBoundingBox() == null) {
            unbounded.add(g);
        } else {
            addObject(g);
        }
    }

    private void collectPolygon(Polygon polygon) {
        int fans = polygon.fanCount();
        boolean transmit = polygon.getMaterial().isTransparent();
        for (int i = 0; i < fans; i++) {
            int k = addTriangle(polygon, i, polygon.fanSharedEdges[i], transmit);
            double[] f = polygon.fan;
            int o = 9 * i;
            outline(k, WatertightTriangle.EDGE_12, f, o + 3, o + 6);
            if (i == 0) outline(k, WatertightTriangle.EDGE_01, f, o, o + 3);
            if (i == fans - 1) outline(k, WatertightTriangle.EDGE_20, f, o + 6, o);
        }
    }

    /**
     * A mesh's triangles with area, in order, each known by its owner and part (its index in the mesh): its vertices
     * stay in the mesh until {@link #copyTriangle} (a million-triangle mesh passes through here). A large mesh is
     * collected on all cores: which triangles have area first, then each one's record at its place.
     */
    private void collectMesh(Mesh mesh) {
        int n = mesh.triangleCount();
        boolean parallel = n >= PARALLEL;
        boolean[] hasArea = new boolean[n];
        // A degenerate triangle is never hit; leaving it out keeps zero-area boxes out of the tree.
        BuildPool.forEach(n, parallel, i -> hasArea[i] = !mesh.isDegenerate(i));
        int kept = 0;
        for (boolean h : hasArea) if (h) kept++;
        // Each kept triangle's place among the kept ones: its own index unless some were left out.
        int[] place = kept < n ? places(hasArea) : null;
        ensureCapacity(count + kept);
        int first = count, owner = kept > 0 ? ownerSlot(mesh) : -1;
        boolean transmit = mesh.getMaterial().isTransparent(), isClear = CompiledPrimitives.isClear(mesh);
        BuildPool.forEach(n, parallel, i -> {
            if (!hasArea[i]) return;
            int k = first + (place == null ? i : place[i]);
            shared[k] = WatertightTriangle.ALL_EDGES_SHARED;
            parts[k] = i;
            owners[k] = owner;
            mayTransmit[k] = transmit;
            clear[k] = isClear;
        });
        count += kept;
    }

    /** Where each kept triangle goes among the kept ones, in order. */
    private static int[] places(boolean[] kept) {
        int[] place = new int[kept.length];
        for (int i = 0, k = 0; i < kept.length; i++) if (kept[i]) place[i] = k++;
        return place;
    }

    /** Fan triangle {@code part} of a polygon, known by its owner and part, as a mesh's triangles are. */
    private int addTriangle(Polygon owner, int part, int sharedFlags, boolean transmit) {
        ensureCapacity(count + 1);
        shared[count] = sharedFlags;
        parts[count] = part;
        owners[count] = ownerSlot(owner);
        mayTransmit[count] = transmit;
        clear[count] = CompiledPrimitives.isClear(owner);
        return count++;
    }

    /**
     * The slot of {@code owner} in {@link #ownerTable}, added there the first time (a mesh's triangles look it up one
     * after the other, so the last slot is tried first).
     */
    private int ownerSlot(Geometry owner) {
        if (ownerCount > 0 && ownerTable[ownerCount - 1] == owner) return ownerCount - 1;
        return ownerSlots.computeIfAbsent(owner, o -> {
            if (ownerCount == ownerTable.length) ownerTable = Arrays.copyOf(ownerTable, 2 * ownerCount);
            ownerTable[ownerCount] = o;
            return ownerCount++;
        });
    }

    /** The geometries that own triangles, each once, in the order first met (a slot's owner at its index). */
    Geometry[] ownerTable() {
        return Arrays.copyOf(ownerTable, ownerCount);
    }

    /** The coordinates triangle primitive {@code k}'s vertices are read from: its mesh's vertices or polygon's fan. */
    private double[] vertexArray(int k) {
        return ownerTable[owners[k]] instanceof Mesh mesh ? mesh.vertices : ((Polygon) ownerTable[owners[k]]).fan;
    }

    /** Where corner {@code corner} (0, 1 or 2) of triangle primitive {@code k} starts in {@link #vertexArray}. */
    private int cornerAt(int k, int corner) {
        int part = parts[k];
        return ownerTable[owners[k]] instanceof Mesh mesh ? 3 * mesh.indices[3 * part + corner] : 9 * part + 3 * corner;
    }

    /** Writes triangle primitive {@code k}'s nine coordinates (three vertices) to {@code out[o..o+9)}. */
    void copyTriangle(int k, double[] out, int o) {
        double[] v = vertexArray(k);
        for (int corner = 0; corner < 3; corner++) System.arraycopy(v, cornerAt(k, corner), out, o + 3 * corner, 3);
    }

    private void addObject(Intersectable g) {
        ensureCapacity(count + 1);
        objects[count] = g;
        objectBoxes[count] = g.getBoundingBox();
        mayTransmit[count] = CompiledPrimitives.mayTransmit(g);
        clear[count] = CompiledPrimitives.isClear(g);
        count++;
    }

    /** Makes room for {@code needed} primitives in all per-primitive arrays (a mesh asks once for all). */
    private void ensureCapacity(int needed) {
        if (needed <= shared.length) return;
        int capacity = Math.max(needed, 2 * shared.length);
        shared = Arrays.copyOf(shared, capacity);
        parts = Arrays.copyOf(parts, capacity);
        owners = Arrays.copyOf(owners, capacity);
        objects = Arrays.copyOf(objects, capacity);
        mayTransmit = Arrays.copyOf(mayTransmit, capacity);
        clear = Arrays.copyOf(clear, capacity);
        objectBoxes = Arrays.copyOf(objectBoxes, capacity);
    }

    private void outline(int primitive, int edgeFlag, double[] v, int from, int to) {
        EdgeKey key = EdgeKey.of(v, from, to);
        outlineEdges.computeIfAbsent(key, e -> new ArrayList<>(2)).add(new int[] {primitive, edgeFlag});
    }

    /** Outline edges used by two or more triangles or polygons become shared (watertight) edges. */
    void markSharedOutlineEdges() {
        for (List<int[]> users : outlineEdges.values()) {
            if (users.size() < 2) continue;
            for (int[] use : users) shared[use[0]] |= use[1];
        }
    }

    /**
     * A box per primitive ({@link BVH#BOX_STRIDE} floats: minimum corner, maximum corner, each with an unused fourth
     * float), padded outward ({@link #BOX_PAD}), then rounded to the nearest float (the BVH's nodes hold floats in the
     * end; half the bytes of doubles for the build to read).
     */
    float[] boxes() {
        float[] boxes = new float[BVH.BOX_STRIDE * count];
        // Each box from its own primitive alone: a large mesh's on all cores.
        BuildPool.forEach(count, count >= PARALLEL, k -> box(k, boxes));
        return boxes;
    }

    /** Primitives from which a mesh is collected and {@link #boxes} made on all cores. */
    private static final int PARALLEL = 1 << 16;

    /** Writes primitive {@code k}'s padded float box to {@code boxes[8k..8k+8)}. */
    private void box(int k, float[] boxes) {
        int b = BVH.BOX_STRIDE * k;
        BoundingBox box = objectBoxes[k];
        if (box != null) {
            padded(boxes, b, 0, box.minX, box.maxX);
            padded(boxes, b, 1, box.minY, box.maxY);
            padded(boxes, b, 2, box.minZ, box.maxZ);
            return;
        }
        double[] v = vertexArray(k);
        int c0 = cornerAt(k, 0), c1 = cornerAt(k, 1), c2 = cornerAt(k, 2);
        for (int a = 0; a < 3; a++) {
            double x = v[c0 + a], y = v[c1 + a], z = v[c2 + a];
            padded(boxes, b, a, Math.min(x, Math.min(y, z)), Math.max(x, Math.max(y, z)));
        }
    }

    /** Writes the bounds {@code lo, hi} on axis {@code a} of the box at {@code boxes[b..]}, padded, as floats. */
    private static void padded(float[] boxes, int b, int a, double lo, double hi) {
        double pad = BOX_PAD * Math.max(Math.abs(lo), Math.abs(hi)) + 0x1p-148;
        // Beyond float's range the nearest float is infinite: a box's near side stays at float's largest value.
        boxes[b + a] = Math.min((float) (lo - pad), Float.MAX_VALUE);
        boxes[b + BVH.BOX_MAX + a] = Math.max((float) (hi + pad), -Float.MAX_VALUE);
    }

    /** An undirected edge between two exact points, for finding shared outline edges. */
    private record EdgeKey(double ax, double ay, double az, double bx, double by, double bz) {
        static EdgeKey of(double[] v, int from, int to) {
            // + 0.0 turns -0.0 into 0.0 so the same point always gives the same key.
            double ax = v[from] + 0.0, ay = v[from + 1] + 0.0, az = v[from + 2] + 0.0;
            double bx = v[to] + 0.0, by = v[to + 1] + 0.0, bz = v[to + 2] + 0.0;
            boolean swap = ax > bx || (ax == bx && (ay > by || (ay == by && az > bz)));
            return swap ? new EdgeKey(bx, by, bz, ax, ay, az) : new EdgeKey(ax, ay, az, bx, by, bz);
        }
    }
}
