package primitives;

/**
 * A {@link Ray} that can be pointed somewhere else: one per render thread, {@link #set} for every ray, so the
 * renderer's hot path creates no ray objects. It holds exactly the values a {@code new Ray(origin, direction)}
 * would, bit for bit, and is checked the same way (finite origin, non-zero finite direction).
 */
public final class ReusableRay extends Ray {
    /** A ray along +z from the origin, to be {@link #set} before use. */
    public ReusableRay() {}

    /**
     * Points this ray from (ox, oy, oz) along (dx, dy, dz), which is normalized here.
     *
     * @param ox the origin's x coordinate, finite
     * @param oy the origin's y coordinate, finite
     * @param oz the origin's z coordinate, finite
     * @param dx the direction's x component, finite
     * @param dy the direction's y component, finite
     * @param dz the direction's z component, finite
     * @return this ray
     * @throws IllegalArgumentException if a coordinate is not finite or the direction is zero
     */
    public ReusableRay set(double ox, double oy, double oz, double dx, double dy, double dz) {
        if (!(Double.isFinite(ox) && Double.isFinite(oy) && Double.isFinite(oz))) {
            throw new IllegalArgumentException(
                    "ray origin must be finite, but was (" + ox + ", " + oy + ", " + oz + ")");
        }
        if (!(Double.isFinite(dx) && Double.isFinite(dy) && Double.isFinite(dz)) || (dx == 0 && dy == 0 && dz == 0)) {
            throw new IllegalArgumentException(
                    "ray direction must be finite and non-zero, but was (" + dx + ", " + dy + ", " + dz + ")");
        }
        init(ox, oy, oz, dx, dy, dz);
        return this;
    }

    /**
     * Points this ray from {@code origin} along {@code direction}.
     *
     * @param origin the new origin; not null
     * @param direction the new direction, any length; not null
     * @return this ray
     */
    public ReusableRay set(Point origin, Vector direction) {
        return set(origin.x, origin.y, origin.z, direction.x, direction.y, direction.z);
    }

    /**
     * Points this ray along {@code ray}'s direction from another origin, copying the direction's derived constants
     * (a translated copy of a ray costs no square root or division).
     *
     * @param ray the ray whose direction to take; not null
     * @param ox the new origin's x, finite
     * @param oy the new origin's y, finite
     * @param oz the new origin's z, finite
     * @return this ray
     * @throws IllegalArgumentException if the origin is not finite
     */
    public ReusableRay setMoved(Ray ray, double ox, double oy, double oz) {
        if (!(Double.isFinite(ox) && Double.isFinite(oy) && Double.isFinite(oz))) {
            throw new IllegalArgumentException(
                    "ray origin must be finite, but was (" + ox + ", " + oy + ", " + oz + ")");
        }
        initMoved(ray, ox, oy, oz);
        return this;
    }
}
