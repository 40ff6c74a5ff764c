package benchmark;

import app.Showcase;
import app.StreetOptions;
import app.StreetScene;
import geometries.Plane;
import geometries.Sphere;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.RayCounters;
import renderer.RenderSettings;
import scene.Scene;

/**
 * What effect planning saves: each scene rendered with planning on and off (median of several runs after a
 * warm-up), with the rays by kind. Planning never changes the image (the tests prove it bit for bit), so the
 * difference is pure cost.
 *
 * <p>Run: {@code mvn -q compile exec:java -Dexec.mainClass=benchmark.PlanningBenchmark [-Dexec.args="runs"]}.
 */
public final class PlanningBenchmark {
    private PlanningBenchmark() {}

    /**
     * Runs the benchmark and prints the table.
     *
     * @param args optionally the number of timed runs per figure, 1 to 1000 (default 5)
     * @throws IllegalArgumentException if the run count is out of range
     */
    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 5;
        if (runs < 1 || runs > 1000) throw new IllegalArgumentException("runs must be in [1, 1000], but was " + runs);
        Map<String, Supplier<Camera.Builder>> scenes = new LinkedHashMap<>();
        scenes.put("matte only (5 spheres, floor, 3 lights), 800x600", () -> matteCamera(800, 600));
        scenes.put(
                "showcase (mirror, glass, 2 soft lights), 400x250", () -> Showcase.camera(Showcase.scene(), 400, 250));
        StreetScene hard = new StreetScene(StreetOptions.HARD), soft = new StreetScene(StreetOptions.soft(10, 16));
        scenes.put("street, hard lamps (6,733 primitives, 12 lights), 800x500", () -> hard.camera(800, 500));
        scenes.put("street, soft lamps (16 rays), 400x250", () -> soft.camera(400, 250));
        System.out.printf(
                Locale.ROOT,
                "%d thread(s), median of %d runs%n%n",
                Runtime.getRuntime().availableProcessors(),
                runs);
        System.out.println("| scene | planned (s) | unplanned (s) | time saved | rays planned | rays unplanned |"
                + " shadow rays saved | secondary rays saved |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|");
        for (Map.Entry<String, Supplier<Camera.Builder>> e : scenes.entrySet()) {
            Result on = measure(e.getValue(), true, runs), off = measure(e.getValue(), false, runs);
            System.out.printf(
                    Locale.ROOT,
                    "| %s | %.3f | %.3f | %.0f%% | %,d | %,d | %,d | %,d |%n",
                    e.getKey(),
                    on.seconds,
                    off.seconds,
                    100 * (1 - on.seconds / off.seconds),
                    on.rays.total(),
                    off.rays.total(),
                    off.rays.shadow - on.rays.shadow,
                    off.rays.reflection + off.rays.refraction - on.rays.reflection - on.rays.refraction);
        }
    }

    private record Result(double seconds, RayCounters rays) {}

    private static Result measure(Supplier<Camera.Builder> camera, boolean planning, int runs) {
        Camera warm = camera.get().build();
        warm.setRenderSettings(warm.getRenderSettings().withPlanEffects(planning))
                .renderImage();
        double[] seconds = new double[runs];
        RayCounters rays = null;
        for (int i = 0; i < runs; i++) {
            Camera c = camera.get().build();
            c.setRenderSettings(c.getRenderSettings().withPlanEffects(planning)).renderImage();
            seconds[i] = c.getLastStatistics().wallSeconds();
            rays = c.getLastStatistics().rays();
        }
        Arrays.sort(seconds);
        return new Result(seconds[runs / 2], rays);
    }

    /** Matte spheres on a floor under a point light, a spot light and a directional light. */
    static Camera.Builder matteCamera(int width, int height) {
        Scene scene = new Scene("matte").setAmbientLight(new AmbientLight(new Color(25, 25, 30)));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(new Material().setKd(0.7)));
        for (int i = 0; i < 5; i++) {
            scene.geometries.add(new Sphere(new Point(-60 + 30 * i, 20 * (i % 2), 12), 12)
                    .setEmission(new Color(30 + 40 * i, 40, 120 - 20 * i))
                    .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(40)));
        }
        scene.lights.add(new PointLight(new Color(300, 280, 250), new Point(-50, -60, 90)).setKl(0.002));
        scene.lights.add(new SpotLight(new Color(250, 250, 300), new Point(60, -40, 80), new Vector(-1, 1, -1.5))
                .setNarrowBeam(3));
        scene.lights.add(new DirectionalLight(new Color(60, 60, 70), new Vector(0.5, 1, -1)));
        return Camera.getBuilder()
                .setLocation(new Point(0, -180, 70))
                .setDirection(new Point(0, 0, 10), Vector.AXIS_Z)
                .setVpDistance(150)
                .setVpSize(160, 120)
                .setResolution(width, height)
                .setRenderSettings(RenderSettings.DEFAULT)
                .setRayTracer(scene, renderer.RayTracerType.SIMPLE);
    }
}
