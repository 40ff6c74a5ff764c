package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Accelerator;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
import geometries.Mesh;
import geometries.Meshes;
import geometries.Plane;
import geometries.Prototype;
import geometries.Sphere;
import java.util.List;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import scene.Scene;

/**
 * A scene of instances renders as the same scene with the prototype copied into place: a shiny mesh, a glass
 * cylinder and a mirror sphere placed six times (turned about tilted axes, scaled, moved), under soft shadows, on a
 * reflective floor. The copy is what a user would build by hand: the mesh's vertices moved by the transform, the
 * sphere and cylinder rebuilt around moved centres and axes.
 *
 * <p>Measured: the 8-bit images are identical, although the two scenes compute every hit on a different path (ray
 * moved into the prototype vs vertices moved into the scene) and the raw colours differ in their last bits. The
 * instanced scene's BVH stores the prototype once. The pieces stand clear of the floor: where two surfaces share a
 * plane (a cylinder's cap lying in the floor), which one a ray meets is decided by rounding, and the two paths round
 * differently (with the glass cylinder's base in the floor's plane, 10 of 9,600 pixels differed, by up to 51 steps).
 */
class InstancedRenderTest {
    private static final Material SHINY =
            new Material().setKd(0.4).setKs(0.5).setShininess(60).setKr(0.15);
    private static final Material GLASS =
            new Material().setKd(0.05).setKs(0.6).setShininess(200).setKt(0.6).setIndexOfRefraction(1.3);
    private static final Material MIRROR = new Material().setKd(0.2).setKr(0.6);

    private static final List<Transform> PLACEMENTS = List.of(
            Transform.translate(-2.2, 0.3, 0),
            Transform.rotateZ(90).then(Transform.translate(0, 0.1, 0)),
            Transform.scale(0.6)
                    .then(Transform.rotate(new Vector(1, 1, 0), 35))
                    .then(Transform.translate(2, -0.4, 0.3)),
            Transform.rotate(new Vector(0.2, -0.3, 1), 200).then(Transform.translate(-1, 2.2, 0)),
            Transform.scale(1.4).then(Transform.rotateX(-15)).then(Transform.translate(1.3, 2.6, 0.2)),
            Transform.scale(0.8).then(Transform.rotateY(60)).then(Transform.translate(3.2, 1.5, 0.4)));

    private static final Mesh BALL = Meshes.icosphere(2);

    private static Geometries prototypeParts() {
        return new Geometries(
                BALL.transformed(Transform.scale(0.45).then(Transform.translate(0, 0, 0.45)))
                        .setMaterial(SHINY),
                new Cylinder(0.25, new Ray(new Point(0.6, 0, 0.05), Vector.AXIS_Z), 0.9).setMaterial(GLASS),
                new Sphere(new Point(-0.55, 0.2, 0.3), 0.3).setMaterial(MIRROR));
    }

    @Test
    void instancesRenderAsTheirCopies() {
        Geometries instances = new Geometries();
        Prototype piece = new Prototype("piece", prototypeParts());
        for (Transform t : PLACEMENTS) instances.add(new Instance(piece, t));
        Geometries copies = new Geometries();
        for (Transform t : PLACEMENTS) copies.add(copy(t));

        Camera instanced = render(instances, 2, true), copied = render(copies, 2, true);
        ImageWriter a = instanced.getImage(), b = copied.getImage();
        int lit = 0, differ = 0, largest = 0;
        String first = null;
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                int[] p = eightBit(a.getPixel(x, y)), q = eightBit(b.getPixel(x, y));
                int d = Math.max(Math.abs(p[0] - q[0]), Math.max(Math.abs(p[1] - q[1]), Math.abs(p[2] - q[2])));
                if (d > 0) {
                    differ++;
                    System.out.println(
                            "DIFF " + x + "," + y + " " + d + " " + a.getPixel(x, y) + " vs " + b.getPixel(x, y));
                    if (first == null)
                        first = "(" + x + ", " + y + "): " + a.getPixel(x, y) + " vs " + b.getPixel(x, y);
                }
                largest = Math.max(largest, d);
                if (p[0] + p[1] + p[2] > 30) lit++;
            }
        }
        System.out.printf(
                "instances vs copies: %d of %d pixels differ in 8 bits, by at most %d; first %s%n",
                differ, a.getNx() * a.getNy(), largest, first);
        assertEquals(0, differ);
        assertTrue(lit > a.getNx() * a.getNy() / 2, "the image shows the scene: " + lit + " lit pixels");

        Accelerator instancedSearch = Accelerator.build(scene(instances).geometries, true);
        Accelerator copiedSearch = Accelerator.build(scene(copies).geometries, true);
        assertEquals(copiedSearch.boundedPrimitiveCount(), instancedSearch.placedPrimitiveCount());
        assertEquals(
                PLACEMENTS.size() + piece.primitiveCount(),
                instancedSearch.storedPrimitiveCount(),
                "the prototype is stored once");
    }

    @Test
    void instancedScenesAreDeterministicAcrossThreadsAndTheBvhSwitch() {
        Geometries instances = new Geometries();
        Prototype piece = new Prototype("piece", prototypeParts());
        for (Transform t : PLACEMENTS) instances.add(new Instance(piece, t));
        ImageWriter reference = render(instances, 2, true).getImage();
        assertNull(FeatureScenes.firstDifference(
                reference, render(instances, 1, true).getImage()));
        assertNull(FeatureScenes.firstDifference(
                reference, render(instances, 2, false).getImage()));
    }

    private static int[] eightBit(Color c) {
        return new int[] {channel(c.getR()), channel(c.getG()), channel(c.getB())};
    }

    private static int channel(double v) {
        return (int) Math.round(Math.max(0, Math.min(255, v)));
    }

    /** The prototype copied into place by {@code t}, which scales uniformly (spheres stay spheres). */
    private static Geometries copy(Transform t) {
        double scale = Math.cbrt(t.determinant());
        Geometries parts = prototypeParts(), copy = new Geometries();
        for (var part : parts.getMembers()) {
            Geometry g = (Geometry) part;
            Geometry moved;
            if (g instanceof Mesh mesh) {
                moved = mesh.transformed(t);
            } else if (g instanceof Sphere s) {
                moved = new Sphere(t.apply(s.getCenter()), s.getRadius() * scale);
            } else {
                Cylinder c = (Cylinder) g;
                Ray axis = c.getAxis();
                moved = new Cylinder(
                        c.getRadius() * scale,
                        new Ray(t.apply(axis.getHead()), t.applyToVector(axis.getDirection())),
                        c.getHeight() * scale);
            }
            copy.add(moved.setMaterial(g.getMaterial()));
        }
        return copy;
    }

    private static Scene scene(Geometries objects) {
        Scene scene = new Scene("instances")
                .setBackground(new Color(12, 14, 24))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.08));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z)
                .setMaterial(new Material().setKd(0.5).setKr(0.15)));
        scene.geometries.add(objects);
        scene.lights.add(new PointLight(new Color(400, 380, 340), new Point(-3, -3, 5))
                .setRadius(0.4)
                .setNumSamples(9));
        scene.lights.add(new DirectionalLight(new Color(50, 50, 70), new Vector(0.4, 1, -1)));
        return scene;
    }

    private static Camera render(Geometries objects, int threads, boolean useBvh) {
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0.5, -6, 3.5))
                .setDirection(new Point(0.5, 1, 0.3), Vector.AXIS_Z)
                .setVpDistance(1)
                .setVpSize(1.2, 0.8)
                .setResolution(120, 80)
                .setRayTracer(scene(objects), RayTracerType.SIMPLE)
                .setBvh(useBvh)
                .setThreads(threads)
                .build();
        camera.renderImage();
        return camera;
    }
}
