package geometries;

import java.util.List;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A convex, planar polygon, validated at construction: at least three vertices, no repeated or back-tracking
 * vertices, all in one plane, turning one way and winding exactly once.
 *
 * <p>The normal comes from Newell's method (robust for any vertex order and for nearly collinear vertices). For
 * intersection the polygon is a fan of triangles from vertex 0 tested with {@link WatertightTriangle}; the fan's
 * inner diagonals are shared edges, so a ray through a diagonal hits exactly one fan triangle, while the
 * polygon's own outline is a boundary (on-edge points are outside unless a neighbouring polygon shares the edge
 * in a compiled scene).
 */
public class Polygon extends Geometry {
    /** Relative tolerance of the planarity and convexity checks. */
    private static final double SHAPE_TOLERANCE = 1e-9;

    private final List<Point> vertices;
    private final Vector normal;
    /** Fan triangles (v0, v[i], v[i+1]) as 9 doubles each. */
    final double[] fan;
    /** Shared-edge flags of each fan triangle: its inner diagonals. */
    final int[] fanSharedEdges;

    /**
     * A polygon of the given vertices, in order around the outline.
     *
     * @param vertices the vertices, at least three
     * @throws IllegalArgumentException if the vertices do not form a convex, planar polygon
     */
    public Polygon(Point... vertices) {
        this(validateVertices(vertices), vertices.length == 3 ? "triangle" : "polygon");
    }

    Polygon(Point[] vertices, String kind) {
        this.vertices = List.of(vertices);
        this.normal = newellNormal(vertices, kind);
        if (vertices.length > 3) {
            checkPlanarAndConvex(vertices, normal);
        }
        int fanCount = vertices.length - 2;
        fan = new double[9 * fanCount];
        fanSharedEdges = new int[fanCount];
        for (int i = 0; i < fanCount; i++) {
            store(fan, 9 * i, vertices[0]);
            store(fan, 9 * i + 3, vertices[i + 1]);
            store(fan, 9 * i + 6, vertices[i + 2]);
            int shared = 0;
            if (i > 0) shared |= WatertightTriangle.EDGE_01; // diagonal v0-v[i+1] shared with the previous fan triangle
            if (i < fanCount - 1) shared |= WatertightTriangle.EDGE_20; // diagonal v[i+2]-v0 shared with the next
            fanSharedEdges[i] = shared;
        }
    }

    private static Point[] validateVertices(Point[] vertices) {
        if (vertices == null || vertices.length < 3) {
            throw new IllegalArgumentException(
                    "a polygon needs at least 3 vertices, but got " + (vertices == null ? "null" : vertices.length));
        }
        for (int i = 0; i < vertices.length; i++) {
            Util.requireNonNull(vertices[i], "vertex " + i);
        }
        return vertices.clone();
    }

    private static void store(double[] array, int offset, Point p) {
        array[offset] = p.x;
        array[offset + 1] = p.y;
        array[offset + 2] = p.z;
    }

    /** Newell's method: the area-weighted normal, exact in sign and stable for nearly collinear vertices. */
    private static Vector newellNormal(Point[] v, String kind) {
        double nx = 0, ny = 0, nz = 0;
        Point c = v[0];
        for (int i = 0; i < v.length; i++) {
            // Relative to v0, so far-away polygons do not lose the normal to cancellation.
            Point a = v[i], b = v[(i + 1) % v.length];
            double ax = a.x - c.x, ay = a.y - c.y, az = a.z - c.z;
            double bx = b.x - c.x, by = b.y - c.y, bz = b.z - c.z;
            nx += Util.differenceOfProducts(ay, bz, az, by);
            ny += Util.differenceOfProducts(az, bx, ax, bz);
            nz += Util.differenceOfProducts(ax, by, ay, bx);
        }
        if (nx == 0 && ny == 0 && nz == 0) {
            throw new IllegalArgumentException(
                    "degenerate " + kind + ": its vertices are collinear or coincide, so it has no area " + List.of(v));
        }
        return new Vector(nx, ny, nz).normalize();
    }

    private static void checkPlanarAndConvex(Point[] v, Vector n) {
        int count = v.length;
        BoundingBox bounds = BoundingBox.of(v);
        double size = bounds.getMin().distance(bounds.getMax());
        // Relative to the polygon's size, plus the rounding of coordinates far from the origin.
        double magnitude = Math.max(
                Math.max(Math.abs(bounds.minX), Math.abs(bounds.maxX)),
                Math.max(
                        Math.max(Math.abs(bounds.minY), Math.abs(bounds.maxY)),
                        Math.max(Math.abs(bounds.minZ), Math.abs(bounds.maxZ))));
        double planeTolerance = SHAPE_TOLERANCE * size + 8 * Math.ulp(magnitude);
        double totalTurn = 0;
        // Coincident neighbours first: the turn test below needs non-zero edges on both sides of each vertex.
        for (int i = 0; i < count; i++) {
            if (v[i].equals(v[(i + 1) % count])) {
                throw new IllegalArgumentException(
                        "polygon vertices " + i + " and " + ((i + 1) % count) + " coincide at " + v[i]);
            }
        }
        for (int i = 0; i < count; i++) {
            Point a = v[i], b = v[(i + 1) % count], c = v[(i + 2) % count];
            double distance = (v[i].x - v[0].x) * n.x + (v[i].y - v[0].y) * n.y + (v[i].z - v[0].z) * n.z;
            if (Math.abs(distance) > planeTolerance) {
                throw new IllegalArgumentException("polygon is not planar: vertex " + i + " " + v[i] + " is "
                        + Math.abs(distance) + " away from the plane of the others");
            }
            Vector e1 = b.subtract(a);
            Vector e2 = c.subtract(b);
            double sin = crossDot(e1, e2, n);
            double cos = e1.dotProduct(e2);
            double scale = e1.length() * e2.length();
            if (sin < -SHAPE_TOLERANCE * scale) {
                throw new IllegalArgumentException(
                        "polygon is not convex: it turns the other way at vertex " + ((i + 1) % count) + " " + b);
            }
            if (Math.abs(sin) <= SHAPE_TOLERANCE * scale && cos < 0) {
                throw new IllegalArgumentException(
                        "polygon touches itself: it doubles back at vertex " + ((i + 1) % count) + " " + b);
            }
            if (Math.abs(sin) <= SHAPE_TOLERANCE * scale) {
                // A vertex on the side between its neighbours makes a zero-area fan triangle and turns part of the
                // outline into a fan diagonal (shared edge), which rays through the outline would then hit.
                throw new IllegalArgumentException("polygon vertex " + ((i + 1) % count) + " " + b
                        + " lies on the side between its neighbours " + a + " and " + c);
            }
            totalTurn += Math.atan2(Math.max(sin, 0), cos);
        }
        if (totalTurn > 3 * Math.PI) {
            throw new IllegalArgumentException(
                    "polygon intersects itself: its outline winds " + Math.round(totalTurn / (2 * Math.PI)) + " times");
        }
    }

    private static double crossDot(Vector a, Vector b, Vector n) {
        double cx = Util.differenceOfProducts(a.y, b.z, a.z, b.y);
        double cy = Util.differenceOfProducts(a.z, b.x, a.x, b.z);
        double cz = Util.differenceOfProducts(a.x, b.y, a.y, b.x);
        return cx * n.x + cy * n.y + cz * n.z;
    }

    /**
     * The vertices, in order.
     *
     * @return the vertex list as given to the constructor
     */
    public List<Point> getVertices() {
        return vertices;
    }

    /** Number of fan triangles the polygon is made of. */
    int fanCount() {
        return fanSharedEdges.length;
    }

    @Override
    public Vector getNormal(Point point) {
        return normal;
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        boolean found = false;
        for (int i = 0; i < fanSharedEdges.length; i++) {
            int o = 9 * i;
            if (WatertightTriangle.intersect(fan, o, o + 3, o + 6, fanSharedEdges[i], ray, tMin, tMax, hit)) {
                tMax = hit.t;
                hit.geometry = this;
                hit.part = i;
                found = true;
            }
        }
        return found;
    }

    @Override
    public BoundingBox getBoundingBox() {
        return BoundingBox.of(vertices.toArray(new Point[0]));
    }

    @Override
    public void completeHit(Ray ray, HitRecord hit) {
        int o = 9 * hit.part;
        WatertightTriangle.completeHit(fan, o, o + 3, o + 6, hit);
        hit.setNormal(normal);
    }
}
