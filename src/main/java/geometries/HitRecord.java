package geometries;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The mutable result of a closest-hit query, reused per thread so that the hot loop allocates nothing.
 *
 * <p>An intersection query fills {@link #t}, {@link #geometry}, {@link #part} and the local coordinates
 * {@link #u}, {@link #v}; {@link Geometry#completeHit} then fills the surface data (point, normals and the bound
 * on the point's floating-point error that spawned rays are offset by). The record also owns the BVH traversal
 * stack, so one record per thread is all the per-ray state the geometry layer needs.
 */
public final class HitRecord {
    /** Distance along the (unit-direction) ray. */
    public double t = Double.POSITIVE_INFINITY;
    /** The geometry that was hit. */
    public Geometry geometry;
    /** Which part of the geometry: the triangle of a mesh or polygon fan, the cap of a cylinder. */
    public int part;
    /** Local surface coordinates: barycentrics b1, b2 for triangles. */
    public double u, v;
    /** Index of the hit primitive in the compiled scene; orders equal-distance hits deterministically. */
    int primitiveIndex = Integer.MAX_VALUE;
    /**
     * The instance that was hit, or null: then {@link #geometry} is the instance's prototype surface and
     * {@link #complete} carries the surface data into scene coordinates.
     */
    public Instance instance;
    /** For a hit on {@link #instance}: the distance along the ray in the prototype's coordinates. */
    double instanceT;
    /** The record of searches inside instances, made on first use (a nested search needs its own stack). */
    private HitRecord inner;
    /** In an inner record: the ray in the prototype's coordinates and the local distance per scene distance. */
    primitives.ReusableRay localRay;

    double localScale;
    /** Whether the current query searches without BVHs (then instances search their prototypes without theirs). */
    boolean withoutBvh;

    /** The hit point, refined onto the surface. */
    public double px, py, pz;
    /** The unit geometric normal; outward for closed shapes, by vertex order for triangles. */
    public double nx, ny, nz;
    /** The unit shading normal (interpolated vertex normals of meshes; otherwise the geometric normal). */
    public double snx, sny, snz;
    /** Per-axis bound on the absolute floating-point error of {@link #point}. */
    public double errorX, errorY, errorZ;

    /** Traversal stack of the BVH: link and count of each postponed child, and where the ray enters its box. */
    final int[] stack = new int[2 * BVH.STACK_SIZE];

    final double[] stackEntry = new double[BVH.STACK_SIZE];
    /** Where the ray enters each child box of the node being visited. */
    final float[] entries = new float[BVH.WIDTH];
    /** The current ray's constants for the box test. */
    final RaySlabs slabs = new RaySlabs();
    /** Beams of shadow rays by slot, made on first use (see {@link Accelerator#aimShadowBeam}). */
    private ShadowBeam[] shadowBeams = new ShadowBeam[0];
    /** Per slot, the beam aimed anew next when none serves (round robin: the one aimed longest ago). */
    private int[] beamVictims = new int[0];
    /** Beams kept per slot. */
    static final int BEAMS_PER_SLOT = 4;
    /** Slots kept (about 2 KB per beam): a scene with more soft lights folds their slots onto these. */
    static final int BEAM_SLOTS = 64;

    /** The beam aimed last, which shadow queries through this record use where it covers their ray. */
    ShadowBeam activeBeam;

    /** Statistics: BVH nodes visited and primitives tested by queries through this record. */
    public long nodeVisits, primitiveTests;

    /**
     * Result of {@link Accelerator#passesLight}: the product of the kT of the transparent surfaces crossed, per
     * channel (1 when nothing is in the way, 0 when blocked).
     */
    public double transmitR, transmitG, transmitB;

    /**
     * The occluder cache of {@link Accelerator#passesLight}: a primitive slot to test first (-1: none), and the slot
     * of the opaque primitive that blocked the last query (-1: none).
     */
    public int occluderHint = -1, occluder = -1;

    /**
     * The flat surface the shadow queries through this record leave (null: none), and which of its triangles (-1:
     * all of it), set by {@link #leaveSurface}. Those queries do not test it: their segments start on it.
     */
    Geometry leaving;

    int leavingPart = -1;

    /**
     * Transparent surfaces a shadow ray crossed: primitive id and kT (red, green, blue), multiplied in id order. An
     * instance adds the product of its own surfaces' kT as one factor.
     */
    int transparentCount;

    private int[] transparentIds = new int[8];
    double[] transparentKt = new double[3 * 8];

    /**
     * Texture coordinates of the hit point, interpolated from the vertices' by {@link Mesh#completeHit} for meshes
     * with texture coordinates; 0 for other geometries (the tracer zeroes them before completing a hit).
     */
    public double texU, texV;

    /**
     * Makes active the beam of {@code slot} that serves segments from near (px, py, pz) toward (cx, cy, cz), or, if
     * none of the slot's {@link #BEAMS_PER_SLOT} does, aims the one of them aimed longest ago; beams are made on first
     * use.
     */
    void aimShadowBeam(
            int slot,
            ShadowQueries queries,
            double px,
            double py,
            double pz,
            double cx,
            double cy,
            double cz,
            double radius) {
        // Slots beyond the last share the last ones' beams (a beam serves only its own light): memory stays bounded.
        slot = slot % BEAM_SLOTS;
        int first = slot * BEAMS_PER_SLOT;
        if (first + BEAMS_PER_SLOT > shadowBeams.length) {
            shadowBeams = java.util.Arrays.copyOf(shadowBeams, first + BEAMS_PER_SLOT);
            beamVictims = java.util.Arrays.copyOf(beamVictims, slot + 1);
        }
        for (int i = first; i < first + BEAMS_PER_SLOT; i++) {
            ShadowBeam beam = shadowBeams[i];
            if (beam != null && beam.serves(queries, px, py, pz, cx, cy, cz, radius)) {
                activeBeam = beam;
                return;
            }
        }
        int victim = first + beamVictims[slot];
        beamVictims[slot] = (beamVictims[slot] + 1) % BEAMS_PER_SLOT;
        if (shadowBeams[victim] == null) shadowBeams[victim] = new ShadowBeam();
        activeBeam = shadowBeams[victim];
        activeBeam.aim(queries, px, py, pz, cx, cy, cz, radius);
    }

    void addTransparentHit(int id, double r, double g, double b) {
        if (transparentCount == transparentIds.length) {
            transparentIds = java.util.Arrays.copyOf(transparentIds, 2 * transparentCount);
            transparentKt = java.util.Arrays.copyOf(transparentKt, 6 * transparentCount);
        }
        transparentIds[transparentCount] = id;
        int o = 3 * transparentCount++;
        transparentKt[o] = r;
        transparentKt[o + 1] = g;
        transparentKt[o + 2] = b;
    }

    /** Insertion sort by primitive id (stable, so hits of one primitive keep their order); lists are tiny. */
    void sortTransparentHits() {
        double[] kt = transparentKt;
        for (int i = 1; i < transparentCount; i++) {
            int id = transparentIds[i];
            double r = kt[3 * i], g = kt[3 * i + 1], b = kt[3 * i + 2];
            int j = i - 1;
            while (j >= 0 && transparentIds[j] > id) {
                transparentIds[j + 1] = transparentIds[j];
                System.arraycopy(kt, 3 * j, kt, 3 * j + 3, 3);
                j--;
            }
            transparentIds[j + 1] = id;
            kt[3 * j + 3] = r;
            kt[3 * j + 4] = g;
            kt[3 * j + 5] = b;
        }
    }

    /**
     * Tells the shadow queries through this record that their segments start on {@code surface}, at a point offset
     * off it toward the side they travel (as the renderer spawns shadow rays), so that where the surface is flat they
     * leave it out: a segment leaving a plane toward one side cannot meet that plane again. Flat means a polygon or
     * triangle (all of it), a plane, or triangle {@code part} of a mesh; any other surface, or null, leaves out
     * nothing. A polygon counts as flat as a whole: it is validated planar, and its fan of triangles bends, if at all,
     * by less than that tolerance, which no surface of the scene is meant to shade itself through. Pass null for a
     * surface inside an instance (its prototype stands in other places too). The setting holds until the next call.
     *
     * @param surface the surface the segments start on, or null
     * @param part the part of it hit ({@link #part}: a mesh's triangle)
     */
    public void leaveSurface(Geometry surface, int part) {
        if (surface instanceof Polygon || surface instanceof Plane) {
            leaving = surface;
            leavingPart = -1;
        } else if (surface instanceof Mesh) {
            leaving = surface;
            leavingPart = part;
        } else {
            leaving = null;
            leavingPart = -1;
        }
    }

    /**
     * Forgets the previous hit so the record can take a new query.
     *
     * @return this record
     */
    public HitRecord reset() {
        t = Double.POSITIVE_INFINITY;
        geometry = null;
        part = 0;
        u = 0;
        v = 0;
        primitiveIndex = Integer.MAX_VALUE;
        instance = null;
        return this;
    }

    /**
     * Fills the surface data (point, normals, error bound) of the hit a closest-hit query left here, in scene
     * coordinates: through the instance when one was hit, otherwise by {@link Geometry#completeHit}.
     *
     * @param ray the ray of the query
     */
    public void complete(Ray ray) {
        if (instance != null) instance.completeHit(ray, this);
        else geometry.completeHit(ray, this);
    }

    /** Adds the node visits and primitive tests of {@code inner}'s last search to this record's, and clears them. */
    void takeStatistics(HitRecord inner) {
        nodeVisits += inner.nodeVisits;
        primitiveTests += inner.primitiveTests;
        inner.nodeVisits = inner.primitiveTests = 0;
    }

    /** The record for searches inside an instance's prototype. */
    HitRecord inner() {
        HitRecord r = inner;
        if (r == null) {
            r = inner = new HitRecord();
            r.localRay = new primitives.ReusableRay();
        }
        return r;
    }

    /**
     * The hit point as a {@link Point} (allocates: for tests and users; the renderer reads the fields).
     *
     * @return a new point of the hit's coordinates
     */
    public Point point() {
        return new Point(px, py, pz);
    }

    /**
     * The geometric normal as a {@link Vector} (allocates).
     *
     * @return a new unit vector of the geometric normal
     */
    public Vector normal() {
        return new Vector(nx, ny, nz);
    }

    /**
     * The shading normal as a {@link Vector} (allocates).
     *
     * @return a new unit vector of the shading normal
     */
    public Vector shadingNormal() {
        return new Vector(snx, sny, snz);
    }

    /**
     * Sets the refined hit point.
     *
     * @param x the hit point's x coordinate
     * @param y the hit point's y coordinate
     * @param z the hit point's z coordinate
     */
    public void setPoint(double x, double y, double z) {
        px = x;
        py = y;
        pz = z;
    }

    /**
     * Sets the geometric normal and, to the same unit vector, the shading normal.
     *
     * @param x the unit normal's x component
     * @param y the unit normal's y component
     * @param z the unit normal's z component
     */
    public void setNormal(double x, double y, double z) {
        nx = snx = x;
        ny = sny = y;
        nz = snz = z;
    }

    /**
     * Sets the geometric normal and the shading normal to {@code n}.
     *
     * @param n the unit normal
     */
    public void setNormal(Vector n) {
        setNormal(n.x, n.y, n.z);
    }

    /**
     * Sets the surface error bound of the hit point.
     *
     * @param ex the error bound along x, at least 0
     * @param ey the error bound along y, at least 0
     * @param ez the error bound along z, at least 0
     */
    public void setError(double ex, double ey, double ez) {
        errorX = ex;
        errorY = ey;
        errorZ = ez;
    }
}
