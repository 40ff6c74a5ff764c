package geometries;

import primitives.Point;
import primitives.Ray;
import primitives.Util;

/**
 * An immutable axis-aligned box: the bounds of geometry for the BVH.
 *
 * <p>The slab test is robust: a zero direction component gives infinite reciprocals, and the NaN of
 * {@code 0 * infinity} (a ray exactly in a slab's plane) is discarded by comparison order instead of spreading;
 * the far distance is enlarged by {@code 1 + 2 gamma(3)} so rounding never culls a box the ray really crosses
 * (Ize 2013, pbrt).
 */
public final class BoundingBox {
    /** Enlargement of the far slab distance that makes the slab test conservative. */
    static final double FAR_SCALE = 1 + 2 * Util.gamma(3);

    /** The box's corners: the minimum and maximum coordinates on each axis. */
    public final double minX, minY, minZ, maxX, maxY, maxZ;

    /**
     * A box of the given extents.
     *
     * @param minX the smallest x
     * @param minY the smallest y
     * @param minZ the smallest z
     * @param maxX the largest x, at least {@code minX}
     * @param maxY the largest y, at least {@code minY}
     * @param maxZ the largest z, at least {@code minZ}
     * @throws IllegalArgumentException if a minimum exceeds its maximum or a coordinate is NaN
     */
    public BoundingBox(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        if (!(minX <= maxX && minY <= maxY && minZ <= maxZ)) {
            throw new IllegalArgumentException("bounding box min must not exceed max (and no NaN), but was (" + minX
                    + ", " + minY + ", " + minZ + ") .. (" + maxX + ", " + maxY + ", " + maxZ + ")");
        }
        this.minX = minX;
        this.minY = minY;
        this.minZ = minZ;
        this.maxX = maxX;
        this.maxY = maxY;
        this.maxZ = maxZ;
    }

    /**
     * The smallest box holding both points.
     *
     * @param a one corner
     * @param b the opposite corner
     * @return a new box
     */
    public static BoundingBox of(Point a, Point b) {
        return new BoundingBox(
                Math.min(a.x, b.x),
                Math.min(a.y, b.y),
                Math.min(a.z, b.z),
                Math.max(a.x, b.x),
                Math.max(a.y, b.y),
                Math.max(a.z, b.z));
    }

    /**
     * The smallest box holding all points.
     *
     * @param points the points, at least one
     * @return a new box
     */
    public static BoundingBox of(Point... points) {
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (Point p : points) {
            x0 = Math.min(x0, p.x);
            y0 = Math.min(y0, p.y);
            z0 = Math.min(z0, p.z);
            x1 = Math.max(x1, p.x);
            y1 = Math.max(y1, p.y);
            z1 = Math.max(z1, p.z);
        }
        return new BoundingBox(x0, y0, z0, x1, y1, z1);
    }

    /** The box around a centre, half extents {@code r}, rounded outward so it surely contains the shape. */
    static BoundingBox around(double cx, double cy, double cz, double rx, double ry, double rz) {
        return new BoundingBox(
                Math.nextDown(cx - rx),
                Math.nextDown(cy - ry),
                Math.nextDown(cz - rz),
                Math.nextUp(cx + rx),
                Math.nextUp(cy + ry),
                Math.nextUp(cz + rz));
    }

    /**
     * The smallest box holding this box and another.
     *
     * @param other the other box
     * @return a new box
     */
    public BoundingBox union(BoundingBox other) {
        return new BoundingBox(
                Math.min(minX, other.minX),
                Math.min(minY, other.minY),
                Math.min(minZ, other.minZ),
                Math.max(maxX, other.maxX),
                Math.max(maxY, other.maxY),
                Math.max(maxZ, other.maxZ));
    }

    /**
     * The surface area, the cost measure of the SAH.
     *
     * @return the total area of the six faces
     */
    public double surfaceArea() {
        double ex = maxX - minX, ey = maxY - minY, ez = maxZ - minZ;
        return 2 * (ex * ey + ey * ez + ez * ex);
    }

    /**
     * The centre point.
     *
     * @return the midpoint of the two corners
     */
    public Point center() {
        return new Point((minX + maxX) * 0.5, (minY + maxY) * 0.5, (minZ + maxZ) * 0.5);
    }

    /**
     * The minimum corner.
     *
     * @return the point (minX, minY, minZ)
     */
    public Point getMin() {
        return new Point(minX, minY, minZ);
    }

    /**
     * The maximum corner.
     *
     * @return the point (maxX, maxY, maxZ)
     */
    public Point getMax() {
        return new Point(maxX, maxY, maxZ);
    }

    /**
     * Whether a point lies in the box, faces included.
     *
     * @param p the point tested
     * @return true when every coordinate lies within the box's extent
     */
    public boolean contains(Point p) {
        return p.x >= minX && p.x <= maxX && p.y >= minY && p.y <= maxY && p.z >= minZ && p.z <= maxZ;
    }

    /**
     * Whether the ray crosses the box somewhere in {@code (tMin, tMax)}.
     *
     * @param ray the ray
     * @param tMin the start of the interval along the ray
     * @param tMax the end of the interval along the ray
     * @return true when the ray may cross the box in the interval (the test is conservative)
     */
    public boolean intersects(Ray ray, double tMin, double tMax) {
        return slabTest(minX, minY, minZ, maxX, maxY, maxZ, ray, tMin, tMax);
    }

    /** The robust slab test on raw bounds, shared with the flat BVH. */
    static boolean slabTest(
            double x0, double y0, double z0, double x1, double y1, double z1, Ray ray, double tMin, double tMax) {
        double near = (x0 - ray.ox()) * ray.invDx();
        double far = (x1 - ray.ox()) * ray.invDx();
        if (ray.invDx() < 0) {
            double s = near;
            near = far;
            far = s;
        }
        far *= FAR_SCALE;
        // "near > tMin" is false for NaN, so a NaN slab leaves the interval unchanged.
        if (near > tMin) tMin = near;
        if (far < tMax) tMax = far;
        if (tMin > tMax) return false;

        near = (y0 - ray.oy()) * ray.invDy();
        far = (y1 - ray.oy()) * ray.invDy();
        if (ray.invDy() < 0) {
            double s = near;
            near = far;
            far = s;
        }
        far *= FAR_SCALE;
        if (near > tMin) tMin = near;
        if (far < tMax) tMax = far;
        if (tMin > tMax) return false;

        near = (z0 - ray.oz()) * ray.invDz();
        far = (z1 - ray.oz()) * ray.invDz();
        if (ray.invDz() < 0) {
            double s = near;
            near = far;
            far = s;
        }
        far *= FAR_SCALE;
        if (near > tMin) tMin = near;
        if (far < tMax) tMax = far;
        return tMin <= tMax;
    }

    // ------------------------------------------------------- the BVH's kernel on outward-rounded float boxes

    /**
     * Bit a is set when the ray runs toward negative axis a (reciprocal direction below zero, -0 included), and
     * {@link #FINITE_RECIPROCALS} when no direction component is zero or subnormal.
     */
    static int directionSigns(Ray ray) {
        boolean finite = Double.isFinite(ray.invDx()) && Double.isFinite(ray.invDy()) && Double.isFinite(ray.invDz());
        return (ray.invDx() < 0 ? 1 : 0)
                | (ray.invDy() < 0 ? 2 : 0)
                | (ray.invDz() < 0 ? 4 : 0)
                | (finite ? FINITE_RECIPROCALS : 0);
    }

    /**
     * Where the ray enters the box at offset {@code o} within {@code (tMin, tMax)}, or {@link #MISS}. The slab test
     * is conservative on both ends (see the class comment), and the ray's direction signs pick which plane of each
     * slab is entered first, so no per-box sorting is needed.
     *
     * <p>For a ray with finite reciprocal directions no slab distance can be NaN, so branch-free min/max
     * (intrinsics on x86) combine them: incoherent rays would mispredict most comparisons. A ray with a zero (or
     * subnormal) direction component gets {@code 0 * inf = NaN} when it lies in a slab's plane; comparisons
     * ignore the NaN there.
     */
    static double entry(float[] boxes, int o, Ray ray, int signs, double tMin, double tMax) {
        // Kept small on purpose: the JIT inlines it into the traversal loop only below 325 bytes of bytecode.
        if ((signs & FINITE_RECIPROCALS) == 0) return entryWithInfiniteReciprocals(boxes, o, ray, signs, tMin, tMax);
        int nearX = (signs & 1) * 3, nearY = (signs >> 1 & 1) * 3 + 1, nearZ = (signs >> 2 & 1) * 3 + 2;
        double near = Math.max(
                Math.max((boxes[o + nearX] - ray.ox()) * ray.invDx(), (boxes[o + nearY] - ray.oy()) * ray.invDy()),
                (boxes[o + nearZ] - ray.oz()) * ray.invDz());
        double far = Math.min(
                Math.min(
                        (boxes[o + 3 - nearX] - ray.ox()) * ray.invDx(),
                        (boxes[o + 5 - nearY] - ray.oy()) * ray.invDy()),
                (boxes[o + 7 - nearZ] - ray.oz()) * ray.invDz());
        near -= Math.abs(near) * SLAB_SLACK;
        far += Math.abs(far) * SLAB_SLACK;
        return (near <= far) & (near <= tMax) & (far >= tMin) ? near : MISS;
    }

    /** {@link #entry} for rays with a zero direction component, whose slab distances may be NaN. */
    private static double entryWithInfiniteReciprocals(
            float[] boxes, int o, Ray ray, int signs, double tMin, double tMax) {
        int nearX = (signs & 1) * 3, nearY = (signs >> 1 & 1) * 3 + 1, nearZ = (signs >> 2 & 1) * 3 + 2;
        double nx = (boxes[o + nearX] - ray.ox()) * ray.invDx();
        double fx = (boxes[o + 3 - nearX] - ray.ox()) * ray.invDx();
        double ny = (boxes[o + nearY] - ray.oy()) * ray.invDy();
        double fy = (boxes[o + 5 - nearY] - ray.oy()) * ray.invDy();
        double nz = (boxes[o + nearZ] - ray.oz()) * ray.invDz();
        double fz = (boxes[o + 7 - nearZ] - ray.oz()) * ray.invDz();
        // "nx > near" is false for NaN, so a NaN slab leaves the interval unchanged.
        double near = tMin, far = tMax;
        if (nx > near) near = nx;
        if (ny > near) near = ny;
        if (nz > near) near = nz;
        if (fx < far) far = fx;
        if (fy < far) far = fy;
        if (fz < far) far = fz;
        near -= Math.abs(near) * SLAB_SLACK;
        far += Math.abs(far) * SLAB_SLACK;
        return near <= far ? near : MISS;
    }

    /** The entry distance of a missed box: no finite hit distance reaches it. */
    static final double MISS = Double.POSITIVE_INFINITY;

    /** Flag in the direction signs: all reciprocal directions are finite, so slab distances are never NaN. */
    static final int FINITE_RECIPROCALS = 8;

    /**
     * Margin on slab distances as a fraction of their magnitude (the 2 gamma(3) of {@link #FAR_SCALE}), applied to
     * both ends so it widens the slab whatever the sign of the distances.
     */
    static final double SLAB_SLACK = 2 * primitives.Util.gamma(3);

    @Override
    public boolean equals(Object obj) {
        return obj instanceof BoundingBox b
                && minX == b.minX
                && minY == b.minY
                && minZ == b.minZ
                && maxX == b.maxX
                && maxY == b.maxY
                && maxZ == b.maxZ;
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(minX, minY, minZ, maxX, maxY, maxZ);
    }

    @Override
    public String toString() {
        return "BoundingBox[(" + minX + ", " + minY + ", " + minZ + ") .. (" + maxX + ", " + maxY + ", " + maxZ + ")]";
    }
}
