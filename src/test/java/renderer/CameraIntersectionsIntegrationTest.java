package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import geometries.Cylinder;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import org.junit.jupiter.api.Test;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * The course integration of camera rays with geometries: a 3 x 3 grid of rays through a 3 x 3 view plane at
 * distance 1, looking along -z with +y up. The rays go through (x, y, -1) relative to the camera, x and y in
 * {-1, 0, 1}. Expected counts are computed by hand in each test's comment.
 */
class CameraIntersectionsIntegrationTest {
    private static final Vector TO = new Vector(0, 0, -1);
    private static final Vector UP = new Vector(0, 1, 0);

    private static Camera camera(Point location) {
        return Camera.getBuilder()
                .setLocation(location)
                .setDirection(TO, UP)
                .setVpDistance(1)
                .setVpSize(3, 3)
                .setResolution(3, 3)
                .setRayTracer(new Scene("integration"), RayTracerType.SIMPLE)
                .build();
    }

    /** Total intersection points of all 9 camera rays with the geometry. */
    private static int countIntersections(Camera camera, Intersectable geometry) {
        int count = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                Ray ray = camera.constructRay(3, 3, j, i);
                count += geometry.findIntersections(ray).size();
            }
        }
        return count;
    }

    @Test
    void cameraRaysGoThroughTheNinePixelCentres() {
        Camera camera = camera(Point.ZERO);
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                Ray ray = camera.constructRay(3, 3, j, i);
                Vector expected = new Vector(j - 1, 1 - i, -1).normalize();
                assertEquals(Point.ZERO, ray.getHead());
                assertEquals(expected.x, ray.getDirection().x, 1e-15, "pixel " + j + "," + i);
                assertEquals(expected.y, ray.getDirection().y, 1e-15, "pixel " + j + "," + i);
                assertEquals(expected.z, ray.getDirection().z, 1e-15, "pixel " + j + "," + i);
            }
        }
    }

    @Test
    void sphere() {
        // TC01: small sphere in front: only the central ray, twice
        assertEquals(2, countIntersections(camera(Point.ZERO), new Sphere(new Point(0, 0, -3), 1)));
        // TC02: camera at (0,0,0.5), sphere (0,0,-2.5) r 2.5: distance^2 of a ray from the centre is
        // 9 - 9 / (x^2 + y^2 + 1) <= 6 < 6.25 for all nine rays: 18
        assertEquals(18, countIntersections(camera(new Point(0, 0, 0.5)), new Sphere(new Point(0, 0, -2.5), 2.5)));
        // TC03: sphere (0,0,-2) r 2: 6.25 - 6.25 / (s + 1) < 4 only for s <= 1 (centre and 4 edge rays): 10
        assertEquals(10, countIntersections(camera(new Point(0, 0, 0.5)), new Sphere(new Point(0, 0, -2), 2)));
        // TC04: the camera inside the sphere: every ray leaves once: 9
        assertEquals(9, countIntersections(camera(Point.ZERO), new Sphere(new Point(0, 0, -2), 4)));
        // TC05: the sphere behind the camera: 0
        assertEquals(0, countIntersections(camera(Point.ZERO), new Sphere(new Point(0, 0, 1), 0.5)));
    }

    @Test
    void plane() {
        Camera camera = camera(Point.ZERO);
        // TC01: parallel to the view plane: 9
        assertEquals(9, countIntersections(camera, new Plane(new Point(0, 0, -5), new Vector(0, 0, 1))));
        // TC02: small angle, z = y/2 - 5: t (1 + y/2) = 5 has t > 0 for every row: 9
        assertEquals(9, countIntersections(camera, new Plane(new Point(0, 0, -5), new Vector(0, -1, 2))));
        // TC03: steep, z = y - 5: t (1 + y) = 5, the bottom row (y = -1) is parallel: 6
        assertEquals(6, countIntersections(camera, new Plane(new Point(0, 0, -5), new Vector(0, -1, 1))));
        // TC04: behind the camera: 0
        assertEquals(0, countIntersections(camera, new Plane(new Point(0, 0, 5), new Vector(0, 0, 1))));
    }

    @Test
    void triangle() {
        Camera camera = camera(Point.ZERO);
        // TC01: small triangle at z = -2: the rays meet z = -2 at (2x, 2y); only (0,0) is inside: 1
        assertEquals(
                1,
                countIntersections(
                        camera, new Triangle(new Point(0, 1, -2), new Point(1, -1, -2), new Point(-1, -1, -2))));
        // TC02: tall triangle: (0,0) and (0,2) (half-width 18/21 there) are inside: 2
        assertEquals(
                2,
                countIntersections(
                        camera, new Triangle(new Point(0, 20, -2), new Point(1, -1, -2), new Point(-1, -1, -2))));
    }

    @Test
    void polygonAndCylinder() {
        Camera camera = camera(Point.ZERO);
        // a square |x|, |y| < 2.5 at z = -2 catches the centre row and column and the corners (2, 2): all 9
        assertEquals(
                9,
                countIntersections(
                        camera,
                        new Polygon(
                                new Point(-2.5, -2.5, -2),
                                new Point(2.5, -2.5, -2),
                                new Point(2.5, 2.5, -2),
                                new Point(-2.5, 2.5, -2))));
        // |x| < 2.5, |y| < 1.5: only the centre row (y = 0) reaches inside: 3
        assertEquals(
                3,
                countIntersections(
                        camera,
                        new Polygon(
                                new Point(-2.5, -1.5, -2),
                                new Point(2.5, -1.5, -2),
                                new Point(2.5, 1.5, -2),
                                new Point(-2.5, 1.5, -2))));
        // a cylinder along the view axis, radius 2.5, from z = -2 to z = -4. At depth d a ray is at radius
        // d sqrt(x^2 + y^2): the centre ray crosses both caps (2); the four edge rays enter the near cap at radius
        // 2 and leave the side at depth 2.5 (2 each); the corner rays are at radius 2.83 already at depth 2 and
        // pass outside: 2 + 4 * 2 = 10
        assertEquals(
                10,
                countIntersections(camera, new Cylinder(2.5, new Ray(new Point(0, 0, -2), new Vector(0, 0, -1)), 2)));
    }
}
