package geometries;

import static primitives.Util.requireNonNull;

import primitives.Point;

/**
 * A triangle: the three-vertex {@link Polygon}. Collinear or coincident vertices are rejected. Its edges are a
 * boundary when it stands alone; in a compiled scene, an edge it shares exactly with another triangle or polygon
 * becomes watertight (see {@link WatertightTriangle}).
 */
public class Triangle extends Polygon {
    /**
     * A triangle of the given vertices.
     *
     * @param p0 the first vertex; not null
     * @param p1 the second vertex; not null
     * @param p2 the third vertex; not null
     * @throws IllegalArgumentException if a vertex is null, or the vertices coincide or are collinear
     */
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
