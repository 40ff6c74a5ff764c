package geometries;

import primitives.Ray;
import primitives.ReusableRay;
import primitives.Vector;

/**
 * Shadow segments tested together, each primitive against all of them in turn rather than each segment against all
 * primitives: the beam of rays from one shading point toward a soft light. Segment i runs from its origin along its
 * unit direction over {@code (0, tMax)}. A primitive's loop over the segments pays the query's set-up once and, for a
 * sphere, runs without the calls and the mispredicted branches of one query per ray (see
 * {@link Accelerator#testsShadowPackets} for where packets apply). Arrays grow to the largest packet and are reused.
 */
public final class ShadowPacket {
    int size;
    /** Segments not blocked yet. */
    int open;
    /** Per segment: origin, unit direction (as a {@link Ray} normalizes it), end, and the direction as given. */
    double[] ox, oy, oz, dx, dy, dz, tMax, vx, vy, vz;
    /** Per segment: whether a primitive tested so far blocks it. */
    boolean[] blocked;

    private final ReusableRay ray = new ReusableRay();

    /** An empty packet. */
    public ShadowPacket() {
        allocate(16);
    }

    private void allocate(int capacity) {
        ox = grow(ox, capacity);
        oy = grow(oy, capacity);
        oz = grow(oz, capacity);
        dx = grow(dx, capacity);
        dy = grow(dy, capacity);
        dz = grow(dz, capacity);
        tMax = grow(tMax, capacity);
        vx = grow(vx, capacity);
        vy = grow(vy, capacity);
        vz = grow(vz, capacity);
        boolean[] b = new boolean[capacity];
        if (blocked != null) System.arraycopy(blocked, 0, b, 0, size);
        blocked = b;
    }

    private double[] grow(double[] a, int capacity) {
        double[] b = new double[capacity];
        if (a != null) System.arraycopy(a, 0, b, 0, size);
        return b;
    }

    /** Empties the packet. */
    public void clear() {
        size = 0;
        open = 0;
    }

    /**
     * Adds the segment from (ox, oy, oz) along (vx, vy, vz) over {@code (0, tMax)}, unblocked.
     *
     * @param ox the origin's x coordinate, finite
     * @param oy the origin's y coordinate, finite
     * @param oz the origin's z coordinate, finite
     * @param vx the direction's x component (any length; finite, not all zero)
     * @param vy the direction's y component
     * @param vz the direction's z component
     * @param tMax the end of the segment along the unit direction
     * @throws IllegalArgumentException as {@link ReusableRay#set} for an origin or direction it refuses
     */
    public void add(double ox, double oy, double oz, double vx, double vy, double vz, double tMax) {
        if (size == blocked.length) allocate(2 * size);
        int i = size;
        // Normalized exactly as a single shadow ray would be (Ray's arithmetic). A factor above 0 means a finite,
        // non-zero direction of ordinary magnitude, the usual case; otherwise, or for an origin that may not be
        // finite, the ray validates (and throws) and normalizes the rare direction.
        double f = Vector.unitFactor(vx, vy, vz);
        if (f > 0 && Double.isFinite(ox + oy + oz)) {
            dx[i] = vx * f;
            dy[i] = vy * f;
            dz[i] = vz * f;
        } else {
            ray.set(ox, oy, oz, vx, vy, vz);
            dx[i] = ray.dx();
            dy[i] = ray.dy();
            dz[i] = ray.dz();
        }
        size++;
        this.ox[i] = ox;
        this.oy[i] = oy;
        this.oz[i] = oz;
        this.tMax[i] = tMax;
        this.vx[i] = vx;
        this.vy[i] = vy;
        this.vz[i] = vz;
        blocked[i] = false;
        open++;
    }

    /**
     * The number of segments.
     *
     * @return the number of segments added since the last {@link #clear}
     */
    public int size() {
        return size;
    }

    /**
     * Whether segment {@code i} is blocked, once the packet has been tested.
     *
     * @param i the segment's index, below {@link #size}
     * @return true when an opaque primitive lies on it
     */
    public boolean blocked(int i) {
        return blocked[i];
    }

    /**
     * The segments not blocked yet.
     *
     * @return how many segments no primitive has blocked so far
     */
    public int open() {
        return open;
    }

    /**
     * Marks segment {@code i} blocked (for an {@link Intersectable#blockAll} of one's own).
     *
     * @param i the segment's index, below {@link #size}
     */
    public void block(int i) {
        if (blocked[i]) return;
        blocked[i] = true;
        open--;
    }

    /**
     * Segment {@code i} as a ray: the packet's own, overwritten by the next call (for an
     * {@link Intersectable#blockAll} of one's own, with {@link #end}).
     *
     * @param i the segment's index, below {@link #size}
     * @return a ray from the segment's origin along its direction, as a single shadow ray would be set
     */
    public Ray segment(int i) {
        return ray.set(ox[i], oy[i], oz[i], vx[i], vy[i], vz[i]);
    }

    /**
     * Where segment {@code i} ends along its ray.
     *
     * @param i the segment's index, below {@link #size}
     * @return the end of the segment's interval {@code (0, end)}
     */
    public double end(int i) {
        return tMax[i];
    }

    /**
     * Tests the open segments one by one with {@code object}'s {@link Intersectable#occludes}: the same query, ray
     * and interval as a single shadow ray's.
     */
    void blockEach(Intersectable object, HitRecord scratch) {
        for (int i = 0; i < size; i++) {
            if (!blocked[i] && object.occludes(segment(i), 0, tMax[i], scratch)) block(i);
        }
    }
}
