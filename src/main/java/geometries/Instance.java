package geometries;

import primitives.Ray;
import primitives.ReusableRay;
import primitives.Transform;
import primitives.Util;

/**
 * A {@link Prototype} placed in the scene by a {@link Transform}, without copying its geometry: the scene's BVH
 * holds the instance's box, and a ray that enters it is carried into the prototype's coordinates and searched
 * through the prototype's own BVH (the two-level BVH of Embree and pbrt).
 *
 * <p>The ray is transformed, not the mesh, and the robustness guarantees of docs/ROBUSTNESS.md carry over: the
 * transformed origin's rounding error is bounded, and the ray starts past that bound (pbrt-v4's offset), so a ray
 * leaving an instance's surface cannot hit that surface again; the hit point is carried back with an error bound
 * that includes the transform's rounding, which is what spawned rays are offset by. Normals are carried by the
 * inverse transpose, so a surface keeps its side: a mirrored (negative-determinant) instance of a closed mesh
 * still has outward normals.
 *
 * <p>A hit on an instance reports the prototype's surface ({@link HitRecord#geometry}: its material and emission)
 * and the instance ({@link HitRecord#instance}); {@link HitRecord#complete} then fills the surface data in scene
 * coordinates. The hot path allocates nothing: the local ray and the inner search state live in the thread's hit
 * record.
 */
public final class Instance implements Intersectable {
    private static final double GAMMA3 = Util.gamma(3);

    private final Prototype prototype;
    private final Transform transform;
    /** Object to world, then world to object: row-major 3 x 4 each. */
    private final double[] toWorld, toLocal;

    private final BoundingBox bounds;
    /** Whether the transform only moves (its linear part is exactly the identity): rays keep their direction. */
    private final boolean moveOnly;

    /**
     * Places {@code prototype} by {@code transform} (from the prototype's coordinates to the scene's).
     *
     * @param prototype the compiled geometry; not null
     * @param transform where and how to place it; not null
     */
    public Instance(Prototype prototype, Transform transform) {
        this.prototype = Util.requireNonNull(prototype, "prototype");
        this.transform = Util.requireNonNull(transform, "instance transform");
        toWorld = transform.toMatrix();
        toLocal = transform.toInverseMatrix();
        bounds = worldBounds(prototype.bounds, toWorld);
        moveOnly = transform.isTranslation();
    }

    /**
     * The placed prototype.
     *
     * @return the prototype, shared with the other instances
     */
    public Prototype prototype() {
        return prototype;
    }

    /**
     * The placement, from the prototype's coordinates to the scene's.
     *
     * @return the transform
     */
    public Transform transform() {
        return transform;
    }

    @Override
    public BoundingBox getBoundingBox() {
        return bounds;
    }

    /** Whether any surface of the prototype may let light through. */
    boolean mayTransmit() {
        return prototype.mayTransmit;
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        HitRecord inner = hit.inner();
        double shift = toLocal(ray, inner);
        double scale = inner.localScale;
        ReusableRay local = inner.localRay;
        inner.reset();
        double localMax = tMax * scale - shift;
        Accelerator search = prototype.search(hit.withoutBvh);
        boolean found = search.intersect(local, Math.max(0, tMin * scale - shift), localMax, inner);
        double t = found ? (inner.t + shift) / scale : 0;
        // Rounding may map a surface at tMin (the one a walk through transparent surfaces just crossed) to just
        // inside the local interval: look on, strictly beyond it.
        while (found && t <= tMin) {
            double from = inner.t;
            inner.reset();
            found = search.intersect(local, from, localMax, inner);
            t = found ? (inner.t + shift) / scale : 0;
        }
        hit.takeStatistics(inner);
        if (!found || !(t < tMax)) return false; // rounding at the far end
        hit.t = t;
        hit.geometry = inner.geometry;
        hit.part = inner.part;
        hit.u = inner.u;
        hit.v = inner.v;
        hit.instance = this;
        hit.instanceT = inner.t;
        return true;
    }

    @Override
    public boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        HitRecord inner = scratch.inner();
        double shift = toLocal(ray, inner);
        double scale = inner.localScale;
        ReusableRay local = inner.localRay;
        inner.occluderHint = -1;
        boolean blocked = prototype
                .search(scratch.withoutBvh)
                .occludes(local, Math.max(0, tMin * scale - shift), tMax * scale - shift, inner);
        scratch.takeStatistics(inner);
        return blocked;
    }

    /**
     * The shadow query through this instance for {@link Accelerator#passesLight}: true when an opaque surface of the
     * prototype blocks the segment; otherwise the product of the kT of its transparent surfaces crossed is added to
     * {@code scratch} as one factor (none when it is exactly 1), under {@code id}. The prototype's own shadow query
     * skips its clear surfaces and stops at the first opaque one, as the scene's does.
     */
    boolean blocksLight(Ray ray, double tMin, double tMax, HitRecord scratch, int id) {
        HitRecord inner = scratch.inner();
        double shift = toLocal(ray, inner);
        double scale = inner.localScale;
        inner.occluderHint = -1;
        boolean passes = prototype
                .search(scratch.withoutBvh)
                .passesLight(inner.localRay, Math.max(0, tMin * scale - shift), tMax * scale - shift, inner);
        scratch.takeStatistics(inner);
        if (!passes) return true;
        double r = inner.transmitR, g = inner.transmitG, b = inner.transmitB;
        if (r != 1 || g != 1 || b != 1) scratch.addTransparentHit(id, r, g, b);
        return false;
    }

    /**
     * Fills the surface data of a hit on this instance in scene coordinates: the prototype's surface completes the
     * hit along the local ray, then point, normals and error bound are carried back.
     *
     * @param ray the scene ray that hit this instance
     * @param hit the record of the hit, which {@link #intersect} filled
     */
    void completeHit(Ray ray, HitRecord hit) {
        HitRecord inner = hit.inner();
        toLocal(ray, inner);
        double t = hit.t;
        hit.t = hit.instanceT;
        hit.geometry.completeHit(inner.localRay, hit);
        hit.t = t;
        double[] m = toWorld;
        double x = hit.px, y = hit.py, z = hit.pz;
        double ex = hit.errorX, ey = hit.errorY, ez = hit.errorZ;
        double tx = m[0] * x, ty = m[1] * y, tz = m[2] * z;
        hit.px = tx + ty + tz + m[3];
        hit.errorX = (GAMMA3 + 1) * (Math.abs(m[0]) * ex + Math.abs(m[1]) * ey + Math.abs(m[2]) * ez)
                + GAMMA3 * (Math.abs(tx) + Math.abs(ty) + Math.abs(tz) + Math.abs(m[3]));
        tx = m[4] * x;
        ty = m[5] * y;
        tz = m[6] * z;
        hit.py = tx + ty + tz + m[7];
        hit.errorY = (GAMMA3 + 1) * (Math.abs(m[4]) * ex + Math.abs(m[5]) * ey + Math.abs(m[6]) * ez)
                + GAMMA3 * (Math.abs(tx) + Math.abs(ty) + Math.abs(tz) + Math.abs(m[7]));
        tx = m[8] * x;
        ty = m[9] * y;
        tz = m[10] * z;
        hit.pz = tx + ty + tz + m[11];
        hit.errorZ = (GAMMA3 + 1) * (Math.abs(m[8]) * ex + Math.abs(m[9]) * ey + Math.abs(m[10]) * ez)
                + GAMMA3 * (Math.abs(tx) + Math.abs(ty) + Math.abs(tz) + Math.abs(m[11]));
        double[] i = toLocal;
        // Normals by the inverse transpose: the columns of the inverse's linear part.
        double nx = i[0] * hit.nx + i[4] * hit.ny + i[8] * hit.nz;
        double ny = i[1] * hit.nx + i[5] * hit.ny + i[9] * hit.nz;
        double nz = i[2] * hit.nx + i[6] * hit.ny + i[10] * hit.nz;
        double n = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz);
        hit.nx = nx * n;
        hit.ny = ny * n;
        hit.nz = nz * n;
        nx = i[0] * hit.snx + i[4] * hit.sny + i[8] * hit.snz;
        ny = i[1] * hit.snx + i[5] * hit.sny + i[9] * hit.snz;
        nz = i[2] * hit.snx + i[6] * hit.sny + i[10] * hit.snz;
        n = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz);
        hit.snx = nx * n;
        hit.sny = ny * n;
        hit.snz = nz * n;
    }

    /**
     * Points {@code inner.localRay} along {@code ray} in the prototype's coordinates, starting past the rounding
     * error of the transformed origin; leaves in {@code inner.localScale} the local distance per scene distance and
     * returns how far the start was moved (local units), so that a local distance {@code s} is the scene distance
     * {@code (s + shift) / scale}.
     */
    private double toLocal(Ray ray, HitRecord inner) {
        ReusableRay local = inner.localRay;
        double[] i = toLocal;
        double ox = ray.ox(), oy = ray.oy(), oz = ray.oz();
        double dx = ray.dx(), dy = ray.dy(), dz = ray.dz();
        double ax = i[0] * ox, ay = i[1] * oy, az = i[2] * oz;
        double lx = ax + ay + az + i[3];
        double errX = GAMMA3 * (Math.abs(ax) + Math.abs(ay) + Math.abs(az) + Math.abs(i[3]));
        ax = i[4] * ox;
        ay = i[5] * oy;
        az = i[6] * oz;
        double ly = ax + ay + az + i[7];
        double errY = GAMMA3 * (Math.abs(ax) + Math.abs(ay) + Math.abs(az) + Math.abs(i[7]));
        ax = i[8] * ox;
        ay = i[9] * oy;
        az = i[10] * oz;
        double lz = ax + ay + az + i[11];
        double errZ = GAMMA3 * (Math.abs(ax) + Math.abs(ay) + Math.abs(az) + Math.abs(i[11]));
        if (moveOnly) {
            // The same direction: its constants are copied, and a scene distance is a local one.
            inner.localScale = 1;
            double shift = Math.abs(dx) * errX + Math.abs(dy) * errY + Math.abs(dz) * errZ;
            local.setMoved(ray, lx + dx * shift, ly + dy * shift, lz + dz * shift);
            return shift;
        }
        double vx = i[0] * dx + i[1] * dy + i[2] * dz;
        double vy = i[4] * dx + i[5] * dy + i[6] * dz;
        double vz = i[8] * dx + i[9] * dy + i[10] * dz;
        local.set(lx, ly, lz, vx, vy, vz);
        // Both rays have unit directions, so a scene distance t is the local distance t * |M^-1 d|.
        inner.localScale = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double ux = local.dx(), uy = local.dy(), uz = local.dz();
        double shift = Math.abs(ux) * errX + Math.abs(uy) * errY + Math.abs(uz) * errZ;
        if (shift > 0) local.setMoved(local, lx + ux * shift, ly + uy * shift, lz + uz * shift);
        return shift;
    }

    /** The scene-space box around the eight transformed corners, widened by their rounding error. */
    private static BoundingBox worldBounds(BoundingBox b, double[] m) {
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX;
        double maxX = Double.NEGATIVE_INFINITY, maxY = maxX, maxZ = maxX;
        for (int c = 0; c < 8; c++) {
            double x = (c & 1) == 0 ? b.minX : b.maxX;
            double y = (c & 2) == 0 ? b.minY : b.maxY;
            double z = (c & 4) == 0 ? b.minZ : b.maxZ;
            for (int row = 0; row < 3; row++) {
                double px = m[4 * row] * x, py = m[4 * row + 1] * y, pz = m[4 * row + 2] * z;
                double v = px + py + pz + m[4 * row + 3];
                double err =
                        GAMMA3 * (Math.abs(px) + Math.abs(py) + Math.abs(pz) + Math.abs(m[4 * row + 3])) + Math.ulp(v);
                if (row == 0) {
                    minX = Math.min(minX, v - err);
                    maxX = Math.max(maxX, v + err);
                } else if (row == 1) {
                    minY = Math.min(minY, v - err);
                    maxY = Math.max(maxY, v + err);
                } else {
                    minZ = Math.min(minZ, v - err);
                    maxZ = Math.max(maxZ, v + err);
                }
            }
        }
        return new BoundingBox(minX, minY, minZ, maxX, maxY, maxZ);
    }

    @Override
    public String toString() {
        return "Instance[" + prototype.name() + ", " + transform + "]";
    }
}
