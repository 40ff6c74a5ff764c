package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;

/**
 * Instances against copies: an instance must find what a copy of its prototype moved into place finds (same hits,
 * same distances and normals to rounding), through the scene's BVH or without it, while storing the prototype once.
 */
class InstanceTest {
    static Stream<Transform> placements() {
        return Stream.of(
                Transform.translate(3, -2, 5),
                Transform.rotateZ(90).then(Transform.translate(-40, 7, 0.5)),
                Transform.scale(2.5)
                        .then(Transform.rotate(new Vector(1, 2, -0.5), 61))
                        .then(Transform.translate(1e4, -3e3, 17)),
                Transform.scale(0.3, 1.7, 1).then(Transform.rotateX(-20)),
                Transform.scale(-1, 1, 1).then(Transform.translate(0, 0, -9)));
    }

    @ParameterizedTest
    @MethodSource("placements")
    void instanceFindsWhatTheCopyFinds(Transform place) {
        Mesh sphere = Meshes.icosphere(3);
        Instance instance = new Instance(new Prototype("ball", sphere), place);
        Mesh copy = sphere.transformed(place);
        BoundingBox box = copy.getBoundingBox();
        Random random = new Random(0x1257A);
        double size = box.getMax().subtract(box.getMin()).length();
        int hits = 0;
        for (int i = 0; i < 2000; i++) {
            Point aim = new Point(
                    box.minX + (box.maxX - box.minX) * random.nextDouble(),
                    box.minY + (box.maxY - box.minY) * random.nextDouble(),
                    box.minZ + (box.maxZ - box.minZ) * random.nextDouble());
            Vector d = new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            Ray ray = new Ray(aim.add(d.normalize().scale(-2 * size)), d);
            HitRecord a = new HitRecord(), b = new HitRecord();
            boolean foundA = instance.intersect(ray, 0, Double.POSITIVE_INFINITY, a);
            boolean foundB = copy.intersect(ray, 0, Double.POSITIVE_INFINITY, b);
            assertEquals(foundB, foundA, "ray " + i + " " + ray + " under " + place);
            if (!foundA) continue;
            hits++;
            assertEquals(b.t, a.t, 1e-10 * (size + b.t), "distance of ray " + i);
            assertSame(sphere, a.geometry);
            assertSame(instance, a.instance);
            a.complete(ray);
            b.complete(ray);
            assertEquals(0, a.point().distance(b.point()), 1e-10 * size, "point of ray " + i);
            if (a.part == b.part) {
                // the copy's normal is by vertex order, which a mirroring placement reverses; the instance keeps
                // the prototype's outward side
                double sign = place.determinant() < 0 ? -1 : 1;
                assertEquals(sign, a.normal().dotProduct(b.normal()), 1e-9, "normal of ray " + i);
            }
            // the hit comes back with an error bound (spawned rays are offset by it; SpawnedRayTest checks them)
            assertTrue(a.errorX + a.errorY + a.errorZ > 0);
        }
        assertTrue(hits > 300, "only " + hits + " rays hit");
    }

    @Test
    void theSceneStoresThePrototypeOnceAndAnswersTheSameWithAndWithoutItsBvh() {
        Mesh ball = Meshes.icosphere(2);
        Prototype prototype = new Prototype("ball", ball);
        Geometries instanced = new Geometries(), copied = new Geometries();
        Random random = new Random(42);
        for (int i = 0; i < 60; i++) {
            Transform t = Transform.scale(4)
                    .then(Transform.rotateZ(360 * random.nextDouble()))
                    .then(Transform.translate(10 * (i % 10), 10 * (i / 10), 0));
            instanced.add(new Instance(prototype, t));
            copied.add(ball.transformed(t));
        }
        Accelerator withBvh = Accelerator.build(instanced, true), bruteForce = Accelerator.build(instanced, false);
        Accelerator copies = Accelerator.build(copied, true);
        assertEquals(60, withBvh.boundedPrimitiveCount());
        assertEquals(60 + ball.triangleCount(), withBvh.storedPrimitiveCount());
        assertEquals(60L * ball.triangleCount(), withBvh.placedPrimitiveCount());
        assertEquals(copies.boundedPrimitiveCount(), withBvh.placedPrimitiveCount());
        assertTrue(
                withBvh.bytes() * 10 < copies.bytes(),
                "instances " + withBvh.bytes() + " bytes, copies " + copies.bytes());
        int hits = 0;
        for (int i = 0; i < 3000; i++) {
            Point from = new Point(-20 + 130 * random.nextDouble(), -20 + 100 * random.nextDouble(), 30);
            Ray ray = new Ray(from, new Vector(random.nextGaussian(), random.nextGaussian(), -3));
            HitRecord a = new HitRecord(), b = new HitRecord(), c = new HitRecord();
            boolean found = withBvh.intersect(ray, 0, Double.POSITIVE_INFINITY, a);
            assertEquals(found, bruteForce.intersect(ray, 0, Double.POSITIVE_INFINITY, b));
            assertEquals(found, copies.intersect(ray, 0, Double.POSITIVE_INFINITY, c), "ray " + i);
            if (!found) continue;
            hits++;
            assertEquals(a.t, b.t, 0, "BVH on and off agree bit for bit");
            assertSame(a.instance, b.instance);
            assertEquals(a.part, b.part);
            assertEquals(c.t, a.t, 1e-9 * (1 + c.t));
            assertEquals(found, withBvh.occludes(ray, 0, Double.POSITIVE_INFINITY, new HitRecord()));
        }
        assertTrue(hits > 500, "only " + hits + " rays hit");
    }

    @Test
    void aCloserPlainSurfaceClearsTheInstanceMark() {
        Instance far = new Instance(new Prototype(new Sphere(Point.ZERO, 1)), Transform.translate(0, 0, -10));
        Sphere near = new Sphere(new Point(0, 0, -5), 1);
        Ray down = new Ray(new Point(0, 0, 10), new Vector(0, 0, -1));
        for (Intersectable scene : List.of(
                new Geometries(far, near),
                Accelerator.build(new Geometries(far, near), true),
                Accelerator.build(new Geometries(far, near), false))) {
            HitRecord hit = new HitRecord();
            assertTrue(scene.intersect(down, 0, Double.POSITIVE_INFINITY, hit));
            assertSame(near, hit.geometry);
            assertEquals(null, hit.instance, "in " + scene.getClass().getSimpleName());
            hit.complete(down);
            assertEquals(new Point(0, 0, -4), hit.point());
        }
    }

    @Test
    void shadowRaysMultiplyTheInstancesTransparentSurfaces() {
        Material tinted = new Material().setKt(new Double3(0.5, 0.8, 0.9));
        Material clearer = new Material().setKt(0.7);
        Geometries panes = new Geometries(
                square(0, tinted), square(1, clearer), square(2, tinted).setMaterial(tinted));
        Prototype prototype = new Prototype("panes", panes);
        Transform t = Transform.rotateY(90).then(Transform.translate(5, 0, 0));
        Accelerator scene = Accelerator.build(new Geometries(new Instance(prototype, t)), true);
        Ray through = new Ray(new Point(-10, 0.2, 0.1), new Vector(1, 0, 0));
        HitRecord scratch = new HitRecord();
        assertTrue(scene.passesLight(through, 0, 100, scratch));
        assertEquals(0.5 * 0.7 * 0.5, scratch.transmitR, 1e-15);
        assertEquals(0.8 * 0.7 * 0.8, scratch.transmitG, 1e-15);
        assertEquals(0.9 * 0.7 * 0.9, scratch.transmitB, 1e-15);
        // an opaque prototype blocks at once
        Accelerator opaque =
                Accelerator.build(new Geometries(new Instance(new Prototype(square(0, new Material())), t)), true);
        assertFalse(opaque.passesLight(through, 0, 100, new HitRecord()));
        assertTrue(opaque.passesLight(through, 0, 14, new HitRecord()), "the pane at x = 5 lies beyond t = 14");
    }

    private static Geometry square(double z, Material material) {
        return new Polygon(new Point(-1, -1, z), new Point(1, -1, z), new Point(1, 1, z), new Point(-1, 1, z))
                .setMaterial(material);
    }

    @Test
    void badPrototypesAreRefusedWithTheReason() {
        Prototype inner = new Prototype("wheel", new Sphere(Point.ZERO, 1));
        Geometries nested = new Geometries(new Instance(inner, Transform.IDENTITY));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Prototype("car", nested))
                .getMessage()
                .contains("cannot be nested"));
        assertTrue(assertThrows(
                        IllegalArgumentException.class,
                        () -> new Prototype("ground", new Plane(Point.ZERO, new Vector(0, 0, 1))))
                .getMessage()
                .contains("unbounded"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Prototype("nothing", new Geometries()))
                .getMessage()
                .contains("empty"));
    }

    @Test
    void boundsHoldTheTransformedPrototype() {
        Mesh ball = Meshes.icosphere(2);
        List<Transform> placements = new ArrayList<>(placements().toList());
        for (Transform t : placements) {
            BoundingBox box = new Instance(new Prototype(ball), t).getBoundingBox();
            double[] v = ball.transformed(t).getVertices();
            for (int i = 0; i < v.length; i += 3) {
                assertTrue(box.contains(new Point(v[i], v[i + 1], v[i + 2])), "vertex " + i / 3 + " under " + t);
            }
        }
    }
}
