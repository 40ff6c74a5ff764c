package renderer;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import geometries.Instance;
import geometries.Mesh;
import geometries.Meshes;
import geometries.Plane;
import geometries.Polygon;
import geometries.Prototype;
import geometries.Sphere;
import java.lang.management.ManagementFactory;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Texture;
import primitives.Transform;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * The render loop allocates (next to) nothing per ray: with one render thread, the bytes that thread allocates
 * between the end of its first tile and the end of its last (read on the thread itself, from the progress
 * listener), over the rays of those tiles, bound the allocation per ray. What is left is per render (the image,
 * the thread's context), not per ray or per pixel. Measured after two warm-up renders, since code the JIT has not
 * compiled yet may allocate where compiled code does not; run with and without the Vector API module (both
 * surefire executions), so both box-test kernels are covered.
 */
class TracerAllocationTest {
    /** Far below the 100 to 400 bytes per ray of the tracer that allocated a ray, points and colours per ray. */
    private static final double MOST_BYTES_PER_RAY = 2;

    @ParameterizedTest(name = "adaptive anti-aliasing {0}")
    @ValueSource(booleans = {false, true})
    void aRenderWithEveryEffectAllocatesNearlyNothingPerRay(boolean adaptive) {
        var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(threads.isCurrentThreadCpuTimeSupported() && threads.isThreadAllocatedMemorySupported());
        threads.setThreadAllocatedMemoryEnabled(true);
        long[] firstAndLast = new long[2];
        boolean[] onRenderThread = new boolean[1];
        Camera camera = camera(adaptive);
        camera.setProgressListener((done, total) -> {
            long bytes = threads.getCurrentThreadAllocatedBytes(); // on the render thread
            if (done == 1) firstAndLast[0] = bytes;
            if (done == total) firstAndLast[1] = bytes;
            onRenderThread[0] = Thread.currentThread().getName().startsWith("render-");
        });
        camera.renderImage();
        camera.renderImage();
        camera.renderImage();
        long bytes = firstAndLast[1] - firstAndLast[0];
        int tiles = (camera.getNx() + 15) / 16 * ((camera.getNy() + 15) / 16);
        // The rays of all tiles but the first, assuming tiles of equal cost (an estimate within a few tens of %).
        double rays = camera.getLastStatistics().rays().total() * (tiles - 1.0) / tiles;
        assertTrue(onRenderThread[0] && tiles > 4, "the counters were read on the render thread, " + tiles + " tiles");
        double perRay = bytes / rays;
        assertTrue(perRay < MOST_BYTES_PER_RAY, bytes + " bytes for " + rays + " rays: " + perRay + " bytes per ray");
    }

    /**
     * Soft and hard shadows, glass, a mirror, a glossy floor and a textured mesh, anti-aliasing and depth of field:
     * every path.
     */
    private static Camera camera(boolean adaptive) {
        Scene scene = new Scene("every effect").setAmbientLight(new AmbientLight(new Color(20, 20, 25)));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z)
                        .setMaterial(new Material().setKd(0.5).setKr(0.3).setRoughness(0.05)),
                new Sphere(new Point(-20, 0, 12), 12)
                        .setMaterial(new Material()
                                .setKd(0.05)
                                .setKs(0.5)
                                .setShininess(200)
                                .setKt(0.8)
                                .setIndexOfRefraction(1.5)),
                new Sphere(new Point(15, 10, 10), 10)
                        .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(40)),
                new Polygon(new Point(-60, 50, 0), new Point(60, 50, 0), new Point(60, 50, 50), new Point(-60, 50, 50))
                        .setMaterial(new Material().setKd(0.1).setKr(0.7)),
                // A textured mesh: the texture lookup and the texture coordinates' interpolation.
                new Mesh(
                                new double[] {-40, -30, 0.5, 0, -30, 0.5, 0, 10, 0.5, -40, 10, 0.5},
                                new int[] {0, 1, 2, 0, 2, 3},
                                null,
                                new double[] {0, 0, 3, 0, 3, 3, 0, 3})
                        .setMaterial(new Material()
                                .setKd(0.8)
                                .setKdMap(new Texture(
                                        2, 2, new float[] {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, Texture.Wrap.MIRROR))));
        // A mesh large enough for the leaf filter (LeafFilter.MIN_MESH), placed by an instance: the filled leaves'
        // kernel must not box its vectors (on JDK 17 a call it cannot inline would).
        Mesh ball = Meshes.icosphere(3);
        ball.setMaterial(new Material().setKd(0.5).setKs(0.2).setShininess(20));
        scene.geometries.add(
                new Instance(new Prototype(ball), Transform.scale(8).then(Transform.translate(35, -10, 8))));
        scene.lights.add(new PointLight(new Color(400, 380, 350), new Point(30, -40, 70))
                .setKq(0.0001)
                .setRadius(5)
                .setNumSamples(9));
        scene.lights.add(new SpotLight(new Color(200, 200, 250), new Point(-40, -30, 60), new Vector(1, 1, -2)));
        scene.lights.add(new DirectionalLight(new Color(40, 40, 50), new Vector(1, 2, -3)));
        return Camera.getBuilder()
                .setLocation(new Point(0, -120, 40))
                .setDirection(new Point(0, 0, 10), Vector.AXIS_Z)
                .setVpDistance(100)
                .setVpSize(80, 60)
                .setResolution(64, 48)
                .setThreads(1)
                .setSamplingConfig(
                        adaptive
                                ? new SamplingConfig(9, TargetShape.RECTANGLE, SamplingPattern.JITTERED).adaptive(2)
                                : new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .setDepthOfField(120, 0.5)
                .setApertureSampling(new SamplingConfig(4, TargetShape.CIRCLE, SamplingPattern.JITTERED))
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true))
                .setRayTracer(scene, RayTracerType.SIMPLE)
                .build();
    }
}
