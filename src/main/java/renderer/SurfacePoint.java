package renderer;

import geometries.Geometry;
import geometries.HitRecord;
import primitives.Point;
import primitives.Vector;

/**
 * A shaded surface point copied out of the thread's {@link HitRecord} (which the next query overwrites): the
 * geometry, the refined point with its error bound, and the geometric and shading normals.
 *
 * <p>{@link #spawnOrigin} is where secondary rays start: the point pushed along the geometric normal, to the
 * side the ray leaves toward, by the projection of the error bound on the normal, then rounded one more ulp away
 * (pbrt-v4's {@code OffsetRayOrigin}). The offset scales with the coordinates, so there is neither acne far from
 * the origin nor a missed thin gap near it, and no fixed epsilon.
 */
public final class SurfacePoint {
    public final Geometry geometry;
    public final Point point;
    public final Vector normal;
    public final Vector shadingNormal;
    private final double errorX, errorY, errorZ;

    /** Copies a completed hit ({@link Geometry#completeHit} must have filled it). */
    public SurfacePoint(HitRecord hit) {
        geometry = hit.geometry;
        point = hit.point;
        normal = hit.normal;
        shadingNormal = hit.shadingNormal;
        errorX = hit.errorX;
        errorY = hit.errorY;
        errorZ = hit.errorZ;
    }

    /** A ray leaving this point in {@code direction}, from the offset origin. */
    public primitives.Ray spawnRay(Vector direction) {
        return new primitives.Ray(spawnOrigin(direction.x, direction.y, direction.z), direction);
    }

    /** The origin of a ray leaving this point in direction (dx, dy, dz). */
    public Point spawnOrigin(double dx, double dy, double dz) {
        double nx = normal.x, ny = normal.y, nz = normal.z;
        double d = Math.abs(nx) * errorX + Math.abs(ny) * errorY + Math.abs(nz) * errorZ;
        if (nx * dx + ny * dy + nz * dz < 0) d = -d;
        double ox = d * nx, oy = d * ny, oz = d * nz;
        return new Point(away(point.x + ox, ox), away(point.y + oy, oy), away(point.z + oz, oz));
    }

    /** Rounds {@code value} one ulp further in the direction of {@code offset}. */
    private static double away(double value, double offset) {
        return offset > 0 ? Math.nextUp(value) : offset < 0 ? Math.nextDown(value) : value;
    }
}
