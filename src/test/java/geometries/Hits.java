package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.List;
import org.junit.jupiter.api.function.Executable;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Assertion helpers shared by the geometry tests. */
final class Hits {
    private Hits() {}

    /** Asserts that {@code actual} are the {@code expected} points, in order, each within {@code tolerance}. */
    static void assertPoints(List<Point> actual, double tolerance, String message, Point... expected) {
        if (actual.size() != expected.length) {
            fail(message + ": expected " + List.of(expected) + " but got " + actual);
        }
        for (int i = 0; i < expected.length; i++) {
            double d = actual.get(i).distance(expected[i]);
            if (!(d <= tolerance)) {
                fail(message + ": point " + i + " expected " + expected[i] + " but got " + actual.get(i) + " (off by "
                        + d + ")");
            }
        }
    }

    /** Asserts the intersections of {@code ray} with {@code geometry} to 1e-10. */
    static void assertHits(Intersectable geometry, Ray ray, String message, Point... expected) {
        assertPoints(geometry.findIntersections(ray), 1e-10, message, expected);
    }

    /** Asserts the ray misses {@code geometry}: an empty list, never null. */
    static void assertMiss(Intersectable geometry, Ray ray, String message) {
        List<Point> points = geometry.findIntersections(ray);
        assertTrue(points != null && points.isEmpty(), message + ": expected no intersections but got " + points);
        assertFalse(geometry.intersect(ray, 0, Double.POSITIVE_INFINITY, new HitRecord()), message);
    }

    static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Point(ox, oy, oz), new Vector(dx, dy, dz));
    }

    /** Asserts an IllegalArgumentException whose message contains every one of {@code fragments}. */
    static IllegalArgumentException assertRejected(Executable construction, String... fragments) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, construction);
        for (String fragment : fragments) {
            assertTrue(
                    e.getMessage() != null && e.getMessage().contains(fragment),
                    "message should name '" + fragment + "': " + e.getMessage());
        }
        return e;
    }

    /** Asserts two unit vectors are equal to 1e-12. */
    static void assertVector(Vector expected, Vector actual, String message) {
        assertEquals(expected.x, actual.x, 1e-12, message + " x: " + actual);
        assertEquals(expected.y, actual.y, 1e-12, message + " y: " + actual);
        assertEquals(expected.z, actual.z, 1e-12, message + " z: " + actual);
    }
}
