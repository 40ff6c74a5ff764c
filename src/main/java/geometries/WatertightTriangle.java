package geometries;

import static primitives.Util.differenceOfProducts;
import static primitives.Util.gamma;

import primitives.Ray;

/**
 * The watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2013), in double precision, shared by
 * {@link Triangle}, {@link Polygon}, {@link Mesh} and the compiled scene so every path gives the same bits.
 *
 * <p>The vertices are translated to the ray origin, permuted so the ray's dominant axis is z, and sheared so
 * the ray becomes the +z axis. The three edge functions are then 2D determinants computed with Kahan's
 * FMA difference of products, whose sign is exact. Two triangles sharing an edge see exactly negated edge
 * functions, so a ray can never pass between them.
 *
 * <p>A point exactly on an edge (edge function zero) is decided by edge flags. An edge that is not shared lies
 * on the outline of the surface and its points are outside (the course contract: a ray through a lone
 * triangle's edge or vertex misses it). An edge shared with another triangle belongs to exactly one of the two by
 * a top-left rule on the edge's sheared direction and the triangle's orientation, so a ray through a shared edge
 * or vertex hits exactly one triangle of a mesh: it never leaks and never double-counts.
 *
 * <p>Finally the hit distance must be conservatively positive, by the error analysis of pbrt-v4 (section 6.8).
 */
public final class WatertightTriangle {
    /** Flag of the edge opposite vertex 0 (from v1 to v2). */
    public static final int EDGE_12 = 1;
    /** Flag of the edge opposite vertex 1 (from v2 to v0). */
    public static final int EDGE_20 = 2;
    /** Flag of the edge opposite vertex 2 (from v0 to v1). */
    public static final int EDGE_01 = 4;
    /** All three edges shared: the setting for closed meshes. */
    public static final int ALL_EDGES_SHARED = EDGE_12 | EDGE_20 | EDGE_01;

    private static final double GAMMA2 = gamma(2);
    private static final double GAMMA3 = gamma(3);
    private static final double GAMMA5 = gamma(5);

    private WatertightTriangle() {}

    /**
     * Intersects the triangle whose vertices are stored as coordinate triples at {@code v[a]}, {@code v[b]} and
     * {@code v[c]} (a flat 9-double triangle uses offsets o, o+3, o+6; an indexed mesh uses 3 * vertex index).
     * On a hit with {@code tMin < t < tMax} writes {@code hit.t}, {@code hit.u = b1}, {@code hit.v = b2} and
     * returns true; otherwise leaves {@code hit} untouched.
     *
     * @param sharedEdges which edges are shared with another triangle ({@link #EDGE_12} etc.)
     * @param v the flat array of vertex coordinates
     * @param a the offset in {@code v} of the first vertex's x
     * @param b the offset in {@code v} of the second vertex's x
     * @param c the offset in {@code v} of the third vertex's x
     * @param ray the ray
     * @param tMin the start of the searched interval, exclusive
     * @param tMax the end of the searched interval, exclusive
     * @param hit the record receiving the hit
     * @return true when the ray hits the triangle in the interval
     */
    public static boolean intersect(
            double[] v, int a, int b, int c, int sharedEdges, Ray ray, double tMin, double tMax, HitRecord hit) {
        return intersect(v, a, b, c, 1, sharedEdges, ray, tMin, tMax, hit);
    }

    /**
     * {@link #intersect(double[], int, int, int, int, Ray, double, double, HitRecord)} for vertices whose coordinates
     * lie {@code stride} apart in {@code v} (x at {@code v[a]}, y at {@code v[a + stride]}, z at
     * {@code v[a + 2 stride]}): the lanes of a BVH leaf ({@link CompiledPrimitives#filtersLeaves}) hold a triangle so.
     */
    static boolean intersect(
            double[] v,
            int a,
            int b,
            int c,
            int stride,
            int sharedEdges,
            Ray ray,
            double tMin,
            double tMax,
            HitRecord hit) {
        // Translate to the ray origin and permute so that z is the ray's dominant axis.
        int kx = ray.kx(), ky = ray.ky(), kz = ray.kz();
        double ox = coordinate(ray, kx), oy = coordinate(ray, ky), oz = coordinate(ray, kz);
        kx *= stride;
        ky *= stride;
        kz *= stride;
        double p0x = v[a + kx] - ox;
        double p0y = v[a + ky] - oy;
        double p0z = v[a + kz] - oz;
        double p1x = v[b + kx] - ox;
        double p1y = v[b + ky] - oy;
        double p1z = v[b + kz] - oz;
        double p2x = v[c + kx] - ox;
        double p2y = v[c + ky] - oy;
        double p2z = v[c + kz] - oz;

        // Shear so the ray runs along +z.
        double sx = ray.shearX(), sy = ray.shearY();
        p0x += sx * p0z;
        p0y += sy * p0z;
        p1x += sx * p1z;
        p1y += sy * p1z;
        p2x += sx * p2z;
        p2y += sy * p2z;

        // Edge functions: exact signs thanks to the FMA difference of products.
        double e0 = differenceOfProducts(p1x, p2y, p1y, p2x);
        double e1 = differenceOfProducts(p2x, p0y, p2y, p0x);
        double e2 = differenceOfProducts(p0x, p1y, p0y, p1x);
        // Edge functions of both signs: the ray passes outside. Decided from their minimum and maximum, which the JIT
        // computes without branches, so a query pays one unpredictable branch per triangle, not a cascade of up to
        // six (in-cache incoherent rays 1.03-1.13x). The same answer: a NaN makes both tests false, and a NaN edge
        // function fails the distance checks below whichever way this goes; -0.0 is neither below nor above 0.
        double lowest = Math.min(e0, Math.min(e1, e2)), highest = Math.max(e0, Math.max(e1, e2));
        if (lowest < 0 & highest > 0) return false;
        double det = e0 + e1 + e2;
        if (det == 0) return false;
        if ((e0 == 0 || e1 == 0 || e2 == 0)
                && !ownsBoundaryPoint(e0, e1, e2, det, sharedEdges, p0x, p0y, p1x, p1y, p2x, p2y)) {
            return false;
        }

        // Distance, scaled by det, compared against the interval without dividing.
        double sz = ray.shearZ();
        p0z *= sz;
        p1z *= sz;
        p2z *= sz;
        double tScaled = e0 * p0z + e1 * p1z + e2 * p2z;
        if (det < 0 ? (tScaled >= 0 || tScaled < tMax * det) : (tScaled <= 0 || tScaled > tMax * det)) {
            return false;
        }
        double invDet = 1 / det;
        double t = tScaled * invDet;
        if (!(t < tMax) || !(t > tMin)) return false;

        // Reject t that rounding error could have made positive (pbrt-v4, "conservatively greater than zero").
        double maxZt = Math.max(Math.abs(p0z), Math.max(Math.abs(p1z), Math.abs(p2z)));
        double deltaZ = GAMMA3 * maxZt;
        double maxXt = Math.max(Math.abs(p0x), Math.max(Math.abs(p1x), Math.abs(p2x)));
        double maxYt = Math.max(Math.abs(p0y), Math.max(Math.abs(p1y), Math.abs(p2y)));
        double deltaX = GAMMA5 * (maxXt + maxZt);
        double deltaY = GAMMA5 * (maxYt + maxZt);
        double deltaE = 2 * (GAMMA2 * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
        double maxE = Math.max(Math.abs(e0), Math.max(Math.abs(e1), Math.abs(e2)));
        double deltaT = 3 * (GAMMA3 * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * Math.abs(invDet);
        if (t <= deltaT) return false;

        hit.t = t;
        hit.u = e1 * invDet;
        hit.v = e2 * invDet;
        return true;
    }

    private static double coordinate(Ray ray, int axis) {
        return axis == 0 ? ray.ox() : axis == 1 ? ray.oy() : ray.oz();
    }

    /**
     * Decides a point on the triangle's boundary (some edge function is zero, none has the wrong sign): inside
     * only if every edge through the point is shared and owned by this triangle.
     */
    private static boolean ownsBoundaryPoint(
            double e0,
            double e1,
            double e2,
            double det,
            int sharedEdges,
            double p0x,
            double p0y,
            double p1x,
            double p1y,
            double p2x,
            double p2y) {
        double orientation = det > 0 ? 1 : -1;
        if (e0 == 0 && !owns(sharedEdges, EDGE_12, p2x - p1x, p2y - p1y, orientation)) return false;
        if (e1 == 0 && !owns(sharedEdges, EDGE_20, p0x - p2x, p0y - p2y, orientation)) return false;
        return e2 != 0 || owns(sharedEdges, EDGE_01, p1x - p0x, p1y - p0y, orientation);
    }

    /**
     * Top-left ownership of a shared edge with direction (dx, dy) in the sheared plane. The neighbour across the
     * edge sees either the reversed direction or the opposite orientation, so exactly one of the two owns it.
     */
    private static boolean owns(int sharedEdges, int edge, double dx, double dy, double orientation) {
        if ((sharedEdges & edge) == 0) return false;
        double ody = orientation * dy;
        return ody > 0 || (ody == 0 && orientation * dx > 0);
    }

    /**
     * Fills the hit point ({@code hit.px, py, pz}) from the barycentrics {@code hit.u = b1}, {@code hit.v = b2} as
     * {@code v0 + b1 (v1 - v0) + b2 (v2 - v0)}, and its per-axis error bound: any barycentrics give a point in
     * the plane, so only the rounding of the edge terms and of the final sum moves the point off the surface.
     */
    static void completeHit(double[] v, int a, int b, int c, HitRecord hit) {
        double b1 = hit.u, b2 = hit.v;
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        double px = v[a] + b1 * e1x + b2 * e2x;
        double py = v[a + 1] + b1 * e1y + b2 * e2y;
        double pz = v[a + 2] + b1 * e1z + b2 * e2z;
        hit.setPoint(px, py, pz);
        double g = gamma(6);
        double g2 = gamma(2);
        hit.setError(
                g * (Math.abs(b1 * e1x) + Math.abs(b2 * e2x)) + g2 * Math.abs(px),
                g * (Math.abs(b1 * e1y) + Math.abs(b2 * e2y)) + g2 * Math.abs(py),
                g * (Math.abs(b1 * e1z) + Math.abs(b2 * e2z)) + g2 * Math.abs(pz));
    }

    /**
     * Whether the triangle has area: its edge cross product, computed as {@link #normal} does, is not zero.
     * Allocation-free, for checking every triangle of a big mesh.
     */
    static boolean hasArea(double[] v, int a, int b, int c) {
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        return differenceOfProducts(e1y, e2z, e1z, e2y) != 0
                || differenceOfProducts(e1z, e2x, e1x, e2z) != 0
                || differenceOfProducts(e1x, e2y, e1y, e2x) != 0;
    }

    /**
     * Sets the hit's geometric and shading normal to the unit normal (v1 - v0) x (v2 - v0), exactly as
     * {@link #normal} computes it; false (and nothing set) if the triangle has no area.
     */
    static boolean setNormal(double[] v, int a, int b, int c, HitRecord hit) {
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        double nx = differenceOfProducts(e1y, e2z, e1z, e2y);
        double ny = differenceOfProducts(e1z, e2x, e1x, e2z);
        double nz = differenceOfProducts(e1x, e2y, e1y, e2x);
        if (nx == 0 && ny == 0 && nz == 0) return false;
        // Vector.normalize's arithmetic.
        double f = primitives.Vector.unitFactor(nx, ny, nz);
        if (f > 0) {
            hit.setNormal(nx * f, ny * f, nz * f);
        } else {
            hit.setNormal(
                    primitives.Vector.unitComponent(nx, nx, ny, nz),
                    primitives.Vector.unitComponent(ny, nx, ny, nz),
                    primitives.Vector.unitComponent(nz, nx, ny, nz));
        }
        return true;
    }

    /** The unit geometric normal (v1 - v0) x (v2 - v0) of a triangle, or null if it has no area. */
    static primitives.Vector normal(double[] v, int a, int b, int c) {
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        double nx = differenceOfProducts(e1y, e2z, e1z, e2y);
        double ny = differenceOfProducts(e1z, e2x, e1x, e2z);
        double nz = differenceOfProducts(e1x, e2y, e1y, e2x);
        if (nx == 0 && ny == 0 && nz == 0) return null;
        return new primitives.Vector(nx, ny, nz).normalize();
    }
}
