package renderer;

import geometries.Geometries;
import geometries.Intersectable;
import geometries.Mesh;
import geometries.Polygon;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;
import lighting.LightSource;
import primitives.Limits;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;

/**
 * What a render needs of the heap, estimated before any work so that a render that cannot fit is refused with the
 * figures instead of failing halfway with an {@code OutOfMemoryError}: the image, the compiled geometry (the
 * accelerator built when the render starts) and, per render thread, the buffers of the largest beams of samples.
 * The estimates are upper bounds measured on this code (docs/CLI.md, "Security model"); what the scene already
 * holds (its meshes) is in the heap in use, so it is not counted again.
 */
public final class RenderMemory {
    /** Image bytes per pixel: three doubles of linear colour, and four bytes of the 8-bit copy made to write it. */
    public static final int BYTES_PER_PIXEL = 28;
    /**
     * Accelerator bytes per primitive (a triangle of a mesh or polygon, a sphere...): coordinates, bounds, BVH
     * nodes and the build's scratch; 150 measured on meshes of 80,000 to 330,000 triangles.
     */
    public static final int BYTES_PER_PRIMITIVE = 160;

    /** One sample offset: two doubles. */
    private static final int BYTES_PER_OFFSET = 16;
    /** One point of a thread's adaptive anti-aliasing lattice: three doubles of colour and a flag, rounded up. */
    private static final int BYTES_PER_LATTICE_POINT = 32;
    /** A render thread's direct-light scratch per light. */
    private static final int BYTES_PER_LIGHT = 128;
    /** A render thread's fixed scratch (rays, records, one shaded point per level). */
    private static final int BYTES_PER_THREAD = 128 << 10;

    private RenderMemory() {}

    /**
     * Refuses, before any work, a render of a {@code width x height} region of the camera's image that would not
     * fit the heap this JVM can still give.
     *
     * @param camera the camera to render with (its scene, samples and threads)
     * @param width the region's width in pixels (the image's for a whole image)
     * @param height the region's height in pixels
     * @throws IllegalStateException naming what the render needs, part by part, and what the JVM can give
     */
    public static void check(Camera camera, int width, int height) {
        check(camera, width, height, RenderMemory::available);
    }

    /** {@link #check(Camera, int, int)} against the heap {@code heap} reports (tests give a small one). */
    static void check(Camera camera, int width, int height, java.util.function.LongSupplier heap) {
        long pixels = (long) width * height;
        // A progressive render also keeps its two halves' sums and sample counts per pixel.
        int perPixel = BYTES_PER_PIXEL + (camera.getProgressive() != null ? ProgressiveSampler.BYTES_PER_PIXEL : 0);
        long image = pixels * perPixel;
        long primitives = primitives(camera.getRayTracer().getScene().geometries);
        if (primitives > Limits.MAX_PRIMITIVES) {
            throw new IllegalStateException(String.format(
                    Locale.ROOT,
                    "the scene has %,d primitives (triangles, spheres...); at most %,d can be rendered",
                    primitives,
                    Limits.MAX_PRIMITIVES));
        }
        long geometry = primitives * BYTES_PER_PRIMITIVE;
        int workers = workers(camera, width, height);
        long threads = workers * threadBytes(camera) + sharedBytes(camera);
        long needed = image + geometry + threads;
        long available = heap.getAsLong();
        if (needed <= available) return;
        // Garbage counts as used until it is collected: confirm the shortfall before refusing the render.
        System.gc();
        available = heap.getAsLong();
        if (needed <= available) return;
        StringBuilder parts = new StringBuilder();
        parts.append(String.format(
                Locale.ROOT, "the %d x %d image %s at %d bytes per pixel", width, height, bytes(image), perPixel));
        if (primitives > 0) {
            parts.append(String.format(Locale.ROOT, ", %,d primitives %s", primitives, bytes(geometry)));
        }
        parts.append(String.format(
                Locale.ROOT, ", %d render thread%s %s", workers, workers == 1 ? "" : "s", bytes(threads)));
        throw new IllegalStateException(String.format(
                Locale.ROOT,
                "the render needs about %s of memory (%s), but this JVM can give %s; render it smaller, with fewer"
                        + " samples or threads, or give Java more memory (-Xmx)",
                bytes(needed),
                parts,
                bytes(available)));
    }

    /**
     * Heap the JVM can still give: its maximum less what is in use (garbage included, until collected).
     *
     * @return bytes
     */
    public static long available() {
        Runtime rt = Runtime.getRuntime();
        return rt.maxMemory() - (rt.totalMemory() - rt.freeMemory());
    }

    /** Render threads the camera starts for a region: one per tile at most, and never above the machine's limit. */
    static int workers(Camera camera, int width, int height) {
        long tiles = (long) ((width + TileRunner.TILE - 1) / TileRunner.TILE)
                * ((height + TileRunner.TILE - 1) / TileRunner.TILE);
        return (int) Math.min(Math.min(camera.getThreads(), Limits.maxThreads()), tiles);
    }

    /** One render thread's buffers: the largest beam of each kind, and the adaptive lattice of a pixel. */
    private static long threadBytes(Camera camera) {
        SamplingConfig aa = camera.getSamplingConfig();
        long bytes = BYTES_PER_THREAD;
        if (aa.isAdaptive()) bytes += (long) aa.getSampleCount() * BYTES_PER_LATTICE_POINT;
        else if (aa.getPattern() != SamplingPattern.GRID) bytes += (long) aa.getSampleCount() * BYTES_PER_OFFSET;
        if (camera.getApertureRadius() > 0) {
            bytes += (long) camera.getApertureSampling().getSampleCount() * BYTES_PER_OFFSET;
        }
        bytes += (long) camera.getRenderSettings().glossySampling().getSampleCount() * BYTES_PER_OFFSET;
        int shadowRays = 0, lights = 0;
        for (LightSource light : camera.getRayTracer().getScene().lights) {
            lights++;
            if (light.isSoft()) shadowRays = Math.max(shadowRays, light.getNumSamples());
        }
        return bytes + (long) shadowRays * BYTES_PER_OFFSET + (long) lights * BYTES_PER_LIGHT;
    }

    /** Buffers shared by the threads: the offsets of a GRID pattern, the same in every pixel. */
    private static long sharedBytes(Camera camera) {
        SamplingConfig aa = camera.getSamplingConfig();
        return aa.getPattern() == SamplingPattern.GRID ? (long) aa.getSampleCount() * BYTES_PER_OFFSET : 0;
    }

    /** The primitives the accelerator will hold: a mesh's triangles, a polygon's fan triangles, one per other. */
    static long primitives(Geometries root) {
        long count = 0;
        Deque<Intersectable> open = new ArrayDeque<>(root.getMembers());
        while (!open.isEmpty()) {
            Intersectable g = open.pop();
            if (g instanceof Geometries group) open.addAll(group.getMembers());
            else if (g instanceof Mesh mesh) count += mesh.triangleCount();
            else if (g instanceof Polygon polygon)
                count += Math.max(1, polygon.getVertices().size() - 2);
            else count++;
        }
        return count;
    }

    /**
     * Bytes in words, for messages.
     *
     * @param bytes a number of bytes
     * @return e.g. "512 MB" or "7.5 GB" (decimal units, rounded up to whole megabytes below a gigabyte)
     */
    public static String bytes(long bytes) {
        return bytes >= 1_000_000_000L
                ? String.format(Locale.ROOT, "%.1f GB", bytes / 1e9)
                : String.format(Locale.ROOT, "%d MB", (bytes + 999_999) / 1_000_000);
    }
}
