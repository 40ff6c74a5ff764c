package geometries;

import static geometries.Hits.assertRejected;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Unit tests for the composite {@link Geometries} (the course partitions for a collection). */
class GeometriesTest {
    private final Sphere sphere = new Sphere(new Point(0, 0, 5), 1); // crossed twice by the z axis
    private final Plane plane = new Plane(new Point(0, 0, 10), Vector.AXIS_Z); // crossed once
    private final Triangle triangle =
            new Triangle(new Point(-1, -1, 2), new Point(1, -1, 2), new Point(0, 1, 2)); // crossed once

    @Test
    void emptyCollection() {
        Geometries empty = new Geometries();
        assertTrue(empty.isEmpty());
        List<Point> points = empty.findIntersections(Hits.ray(0, 0, 0, 0, 0, 1));
        assertTrue(points != null && points.isEmpty());
        assertNull(empty.getBoundingBox());
    }

    @Test
    void noShapeIsHit() {
        Geometries g = new Geometries(sphere, plane, triangle);
        assertTrue(g.findIntersections(Hits.ray(5, 5, 0, 1, 0, 0)).isEmpty());
    }

    @Test
    void oneShapeIsHit() {
        Geometries g = new Geometries(sphere, plane, triangle);
        // upward from z = 7: only the plane
        Hits.assertHits(g, Hits.ray(0, 0, 7, 0, 0, 1), "only the plane", new Point(0, 0, 10));
    }

    @Test
    void someShapesAreHit() {
        Geometries g = new Geometries(sphere, plane, triangle);
        // upward from z = 3: sphere twice and the plane
        Hits.assertHits(
                g,
                Hits.ray(0, 0, 3, 0, 0, 1),
                "sphere and plane",
                new Point(0, 0, 4),
                new Point(0, 0, 6),
                new Point(0, 0, 10));
    }

    @Test
    void allShapesAreHitNearestFirst() {
        Geometries g = new Geometries(plane, sphere, triangle);
        Ray up = Hits.ray(0, 0, 0, 0, 0, 1);
        Hits.assertHits(g, up, "all", new Point(0, 0, 2), new Point(0, 0, 4), new Point(0, 0, 6), new Point(0, 0, 10));
        HitRecord hit = new HitRecord();
        assertTrue(g.intersect(up, 0, Double.POSITIVE_INFINITY, hit));
        assertSame(triangle, hit.geometry);
        assertTrue(g.occludes(up, 0, 3, new HitRecord()));
        assertTrue(!g.occludes(up, 0, 1.9, new HitRecord()));
    }

    @Test
    void nestedCollectionsAndFluentAdd() {
        Geometries inner = new Geometries(sphere);
        Geometries outer = new Geometries();
        assertSame(outer, outer.add(inner, triangle));
        assertEquals(List.of(inner, triangle), outer.getMembers());
        assertThrows(
                UnsupportedOperationException.class, () -> outer.getMembers().add(plane));
        assertEquals(3, outer.findIntersections(Hits.ray(0, 0, 0, 0, 0, 1)).size());
    }

    @Test
    void badMembersAreRejected() {
        Geometries g = new Geometries();
        assertRejected(() -> g.add(sphere, null), "geometry 1");
        assertRejected(() -> g.add((Intersectable[]) null), "geometries");
        assertRejected(() -> g.add(g), "itself");
        assertTrue(g.isEmpty(), "a rejected add leaves the collection unchanged");
    }

    @Test
    void boundingBoxIsTheUnionOrNullWhenUnbounded() {
        Geometries bounded = new Geometries(sphere, triangle);
        BoundingBox box = bounded.getBoundingBox();
        assertEquals(-1, box.minX, 1e-12);
        assertEquals(-1, box.minY, 1e-12);
        assertEquals(2, box.minZ, 1e-12);
        assertEquals(6, box.maxZ, 1e-12);
        assertNull(new Geometries(sphere, plane).getBoundingBox());
        assertNull(new Geometries(new Geometries(plane), sphere).getBoundingBox());
    }
}
