package benchmark;

import geometries.Accelerator;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
import geometries.Mesh;
import geometries.Meshes;
import geometries.Plane;
import geometries.Prototype;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.function.Supplier;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * What instancing saves: a grove of the same tree (a 5,120-triangle crown on a trunk) placed {@code side x side}
 * times, turned and scaled at random, once as instances of one prototype and once as copies moved into place. Prints
 * the primitives stored, the search structure's bytes, the build time and the render time (median of the runs, one
 * warm-up render first; 16 camera rays per pixel, one hard light) of each, and their ratios. {@code raytracer benchmark instancing [runs side]}.
 */
public final class InstancingBenchmark {
    private static final int WIDTH = 480, HEIGHT = 300, THREADS = 2;

    private InstancingBenchmark() {}

    /**
     * Runs the benchmark and prints a Markdown table.
     *
     * @param args optionally the number of runs (default 3) and the grove's side (default 16: 256 trees)
     */
    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 3;
        int side = args.length > 1 ? Integer.parseInt(args[1]) : 16;
        if (runs < 1 || runs > 100) throw new IllegalArgumentException("runs must be 1 to 100, but was " + runs);
        if (side < 1 || side > 64) throw new IllegalArgumentException("side must be 1 to 64, but was " + side);
        List<Transform> placements = placements(side);
        Supplier<Geometries> instanced = () -> {
            Prototype tree = new Prototype("tree", tree());
            Geometries grove = new Geometries();
            for (Transform t : placements) grove.add(new Instance(tree, t));
            return grove;
        };
        Supplier<Geometries> copied = () -> {
            Geometries grove = new Geometries();
            for (Transform t : placements) grove.add(copy(t));
            return grove;
        };
        int treePrimitives = new Prototype("tree", tree()).primitiveCount();
        System.out.printf(
                Locale.ROOT,
                "%d trees of %d primitives, %dx%d, 16 HALTON camera rays per pixel, %d threads, median of %d runs%n%n",
                placements.size(),
                treePrimitives,
                WIDTH,
                HEIGHT,
                THREADS,
                runs);
        System.out.println(
                "| scene | primitives stored | search structure | make + build | render (wall, with its build) | tracing alone | M rays/s traced |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|");
        double[] a = measure("instances", instanced, runs), b = measure("copies", copied, runs);
        System.out.printf(
                Locale.ROOT,
                "| copies / instances | %.0fx | %.0fx | %.1fx | %.2fx | %.2fx | |%n",
                b[0] / a[0],
                b[1] / a[1],
                b[2] / a[2],
                b[3] / a[3],
                b[4] / a[4]);
    }

    /**
     * Stored primitives, bytes, seconds to make the scene's geometry and build its search structure (the prototype's
     * own BVH included), and seconds of the render; prints the row.
     */
    private static double[] measure(String name, Supplier<Geometries> geometry, int runs) {
        double[] builds = new double[runs], renders = new double[runs], traces = new double[runs];
        Accelerator search = null;
        double rays = 0;
        render(scene(geometry.get())); // warm-up: class loading and JIT
        for (int i = 0; i < runs; i++) {
            long start = System.nanoTime();
            Scene scene = scene(geometry.get());
            search = Accelerator.build(scene.geometries, true);
            builds[i] = (System.nanoTime() - start) * 1e-9;
            Camera camera = render(scene);
            renders[i] = camera.getLastStatistics().wallSeconds();
            traces[i] = renders[i] - camera.getLastStatistics().preparationSeconds();
            rays = camera.getLastStatistics().rays().total();
        }
        double build = median(builds), render = median(renders), trace = median(traces);
        System.out.printf(
                Locale.ROOT,
                "| %s | %,d | %.1f MB | %.3f s | %.3f s | %.3f s | %.2f |%n",
                name,
                search.storedPrimitiveCount(),
                search.bytes() / 1e6,
                build,
                render,
                trace,
                rays / trace * 1e-6);
        return new double[] {search.storedPrimitiveCount(), search.bytes(), build, render, trace};
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    private static Camera render(Scene scene) {
        Camera camera = Camera.getBuilder()
                .setLocation(new Point(0, -60, 30))
                .setDirection(new Point(0, 0, 0), Vector.AXIS_Z)
                .setVpDistance(1)
                .setVpSize(1.6, 1)
                .setResolution(WIDTH, HEIGHT)
                .setSamplingConfig(new SamplingConfig(16, TargetShape.RECTANGLE, SamplingPattern.HALTON))
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .setThreads(THREADS)
                .build();
        camera.renderImage();
        return camera;
    }

    private static Scene scene(Geometries objects) {
        Scene scene = new Scene("grove")
                .setBackground(new Color(20, 30, 50))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.6)));
        scene.geometries.add(objects);
        scene.lights.add(new PointLight(new Color(900, 850, 800), new Point(-40, -30, 60)));
        return scene;
    }

    /** The tree in its own coordinates: trunk from the ground, a crown of 5,120 triangles. */
    private static Geometries tree() {
        return new Geometries(
                new Cylinder(0.25, new Ray(Point.ZERO, Vector.AXIS_Z), 2)
                        .setMaterial(new Material().setKd(0.5).setKs(0.1)),
                Meshes.icosphere(4)
                        .transformed(Transform.scale(1.2).then(Transform.translate(0, 0, 2.8)))
                        .setMaterial(new Material().setKd(0.6).setKs(0.2).setShininess(20)));
    }

    /** A grid of trees 4 apart, each turned about z and scaled by 0.8 to 1.2 (seeded). */
    private static List<Transform> placements(int side) {
        Random random = new Random(0x7EE5);
        List<Transform> list = new ArrayList<>();
        for (int i = 0; i < side; i++) {
            for (int j = 0; j < side; j++) {
                list.add(Transform.scale(0.8 + 0.4 * random.nextDouble())
                        .then(Transform.rotateZ(360 * random.nextDouble()))
                        .then(Transform.translate(4 * (i - side / 2.0), 4 * j, 0)));
            }
        }
        return list;
    }

    /** The tree copied into place by {@code t} (which scales uniformly): what a scene without instancing holds. */
    private static Geometries copy(Transform t) {
        double scale = Math.cbrt(t.determinant());
        Geometries copy = new Geometries();
        for (var part : tree().getMembers()) {
            Geometry g = (Geometry) part;
            if (g instanceof Mesh mesh) {
                copy.add(mesh.transformed(t));
            } else {
                Cylinder c = (Cylinder) g;
                copy.add(new Cylinder(
                                c.getRadius() * scale,
                                new Ray(
                                        t.apply(c.getAxis().getHead()),
                                        t.applyToVector(c.getAxis().getDirection())),
                                c.getHeight() * scale)
                        .setMaterial(g.getMaterial()));
            }
        }
        return copy;
    }
}
