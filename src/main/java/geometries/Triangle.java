package geometries;

import static primitives.Util.requireNonNull;

import primitives.Point;

/**
 * A triangle: the three-vertex {@link Polygon}. Collinear or coincident vertices are rejected. Its edges are a
 * boundary when it stands alone; in a compiled scene, an edge it shares exactly with another triangle or polygon
 * becomes watertight (see {@link WatertightTriangle}).
 */
public class Triangle extends Polygon {
    public Triangle(Point p0, Point p1, Point p2) {
        super(
                new Point[] {
                    requireNonNull(p0, "triangle vertex p0"),
                    requireNonNull(p1, "triangle vertex p1"),
                    requireNonNull(p2, "triangle vertex p2")
                },
                "triangle");
    }
}
