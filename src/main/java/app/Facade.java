package app;

import geometries.Geometry;
import geometries.Polygon;
import primitives.Point;

/**
 * The coordinate frame of an axis-aligned house front: {@code u} runs along the front, {@code v} up and {@code w}
 * out of the wall toward the street, so windows, signs and ledges are placed the same way on either side of the
 * street and across its end.
 *
 * @param origin the point at u = v = w = 0 (on the wall, at ground level)
 * @param uAxis the axis u runs along: 0 for x, 1 for y
 * @param uSign +1 or -1: the direction of u along that axis
 * @param wSign +1 or -1: the direction of w (toward the street) along the other horizontal axis
 */
record Facade(Point origin, int uAxis, int uSign, int wSign) {

    /** The scene point at facade coordinates (u, v, w). */
    Point at(double u, double v, double w) {
        double along = uSign * u, out = wSign * w;
        return uAxis == 0
                ? new Point(origin.x + along, origin.y + out, origin.z + v)
                : new Point(origin.x + out, origin.y + along, origin.z + v);
    }

    /**
     * The rectangle u0..u1 by v0..v1 at distance {@code w} in front of the wall, wound so that its normal points
     * out of the wall (toward the street).
     */
    Geometry rectangle(double u0, double u1, double v0, double v1, double w) {
        Point a = at(u0, v0, w), b = at(u1, v0, w), c = at(u1, v1, w), d = at(u0, v1, w);
        // u x v points out of the wall for a right-handed frame (u, v, w); otherwise reverse the outline.
        return rightHanded() ? new Polygon(a, b, c, d) : new Polygon(a, d, c, b);
    }

    /** The axis-aligned box u0..u1, v0..v1, w0..w1, added to {@code mesh}. */
    void box(MeshBuilder mesh, double u0, double u1, double v0, double v1, double w0, double w1) {
        Point a = at(u0, v0, w0), b = at(u1, v1, w1);
        mesh.box(Math.min(a.x, b.x), Math.min(a.y, b.y), a.z, Math.max(a.x, b.x), Math.max(a.y, b.y), b.z);
    }

    /** Whether (u, v, w) is a right-handed frame in the scene's right-handed (x, y, z). */
    private boolean rightHanded() {
        // u along x, w along y: u x z = -y (scaled by uSign), so right-handed iff w points along -uSign y.
        // u along y, w along x: u x z = +x (scaled by uSign), so right-handed iff w points along +uSign x.
        return uAxis == 0 ? wSign == -uSign : wSign == uSign;
    }
}
