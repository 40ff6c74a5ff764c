package renderer;

import geometries.Geometry;
import geometries.HitRecord;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A shaded surface point copied out of the thread's {@link HitRecord} (which the next query overwrites): the
 * geometry, the refined point with its error bound, and the geometric and shading normals. The tracer keeps one
 * per recursion level and per thread and {@link #set}s it for every hit, so shading allocates nothing.
 *
 * <p>{@link #spawn} computes where secondary rays start: the point pushed along the geometric normal, to the side
 * the ray leaves toward, by the projection of the error bound on the normal, then rounded one more ulp away
 * (pbrt-v4's {@code OffsetRayOrigin}). The offset scales with the coordinates, so there is neither acne far from
 * the origin nor a missed thin gap near it, and no fixed epsilon.
 */
public final class SurfacePoint {
    /** The geometry hit. */
    public Geometry geometry;
    /** The refined hit point. */
    public double px, py, pz;
    /** The unit geometric normal. */
    public double nx, ny, nz;
    /** The unit shading normal. */
    public double snx, sny, snz;

    /** The hit point's texture coordinates (0 where the geometry has none). */
    public double texU, texV;

    /** The part of the geometry hit ({@link HitRecord#part}: a mesh's triangle). */
    public int part;
    /** Whether the geometry was hit inside an instance (then it stands in other places too). */
    public boolean inInstance;

    private double errorX, errorY, errorZ;
    /** The origin the last {@link #spawn} computed. */
    public double originX, originY, originZ;

    /** Two directions across the last direction given to {@link #basis}: where beams around it spread. */
    public double e1x, e1y, e1z, e2x, e2y, e2z;

    /** The average of a beam of rays leaving this point (glossy reflection, frosted refraction). */
    final ColorAverage beamAverage = new ColorAverage();

    /** An empty point, to be {@link #set} before use. */
    public SurfacePoint() {}

    /**
     * Copies a completed hit ({@link Geometry#completeHit} must have filled it).
     *
     * @param hit the completed hit record
     */
    public SurfacePoint(HitRecord hit) {
        set(hit);
    }

    /**
     * Copies a completed hit into this point.
     *
     * @param hit the completed hit record
     * @return this point
     */
    public SurfacePoint set(HitRecord hit) {
        geometry = hit.geometry;
        px = hit.px;
        py = hit.py;
        pz = hit.pz;
        nx = hit.nx;
        ny = hit.ny;
        nz = hit.nz;
        snx = hit.snx;
        sny = hit.sny;
        snz = hit.snz;
        errorX = hit.errorX;
        errorY = hit.errorY;
        errorZ = hit.errorZ;
        texU = hit.texU;
        texV = hit.texV;
        part = hit.part;
        inInstance = hit.instance != null;
        return this;
    }

    /**
     * The point (allocates; the tracer reads the fields).
     *
     * @return a new point of the position
     */
    public Point point() {
        return new Point(px, py, pz);
    }

    /**
     * The geometric normal (allocates).
     *
     * @return a new unit vector of the geometric normal
     */
    public Vector normal() {
        return new Vector(nx, ny, nz);
    }

    /**
     * The shading normal (allocates).
     *
     * @return a new unit vector of the shading normal
     */
    public Vector shadingNormal() {
        return new Vector(snx, sny, snz);
    }

    /**
     * A ray leaving this point in {@code direction}, from the offset origin.
     *
     * @param direction the direction of the new ray
     * @return a new ray from the offset origin
     */
    public Ray spawnRay(Vector direction) {
        return new Ray(spawnOrigin(direction.x, direction.y, direction.z), direction);
    }

    /**
     * The origin of a ray leaving this point in direction (dx, dy, dz) (allocates; see {@link #spawn}).
     *
     * @param dx the ray direction's x component
     * @param dy the ray direction's y component
     * @param dz the ray direction's z component
     * @return a new point: the offset origin
     */
    public Point spawnOrigin(double dx, double dy, double dz) {
        spawn(dx, dy, dz);
        return new Point(originX, originY, originZ);
    }

    /**
     * Sets {@link #originX}, {@code originY}, {@code originZ} to the origin of a ray leaving in (dx, dy, dz).
     *
     * @param dx the ray direction's x component
     * @param dy the ray direction's y component
     * @param dz the ray direction's z component
     */
    public void spawn(double dx, double dy, double dz) {
        double d = Math.abs(nx) * errorX + Math.abs(ny) * errorY + Math.abs(nz) * errorZ;
        if (nx * dx + ny * dy + nz * dz < 0) d = -d;
        double ox = d * nx, oy = d * ny, oz = d * nz;
        originX = away(px + ox, ox);
        originY = away(py + oy, oy);
        originZ = away(pz + oz, oz);
    }

    /**
     * Sets {@code e1} to {@code d.perpendicular()} and {@code e2} to {@code d.crossProduct(e1)} for the unit
     * direction d = (x, y, z), with exactly the arithmetic of {@link Vector#perpendicular()} and
     * {@link Vector#crossProduct} (Duff et al. 2017; cross products by {@link Util#differenceOfProducts}).
     *
     * @param x the unit direction's x component
     * @param y the unit direction's y component
     * @param z the unit direction's z component
     */
    public void basis(double x, double y, double z) {
        double sign = Math.copySign(1.0, z);
        double a = -1.0 / (sign + z);
        double b = x * y * a;
        e1x = 1.0 + sign * x * x * a;
        e1y = sign * b;
        e1z = -sign * x;
        e2x = Util.differenceOfProducts(y, e1z, z, e1y);
        e2y = Util.differenceOfProducts(z, e1x, x, e1z);
        e2z = Util.differenceOfProducts(x, e1y, y, e1x);
    }

    /** Rounds {@code value} one ulp further in the direction of {@code offset}. */
    private static double away(double value, double offset) {
        return offset > 0 ? Math.nextUp(value) : offset < 0 ? Math.nextDown(value) : value;
    }
}
