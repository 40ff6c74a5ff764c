package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import app.Landmark;
import app.StreetOptions;
import app.StreetScene;
import geometries.Accelerator;
import geometries.Geometries;
import geometries.HitRecord;
import geometries.Intersectable;
import geometries.Mesh;
import geometries.Sphere;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/**
 * The street scene rendered with every feature off and on: anti-aliasing, soft shadows (plain and adaptive), the
 * BVH, one and all threads. Writes {@code images/street.png} (plain), {@code images/street2.png} (every feature
 * on), the variants as {@code images/street-*.png} and the timing table {@code images/street-timings.md}.
 *
 * <p>By default it renders a quick preview; {@code mvn test -Dtest=StreetSceneTest -Dstreet.quality=full} renders
 * the README picture (see {@link StreetQuality}). Timings are printed and written, never asserted.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class StreetSceneTest {
    private static final StreetQuality QUALITY = StreetQuality.fromSystemProperty();
    /** Lamp radius of the soft-shadow variants, in scene units (50 cm): the size of the glass globes. */
    private static final double LAMP_RADIUS = 10;
    /** At least two threads even on one processor, so the thread comparison always splits the image. */
    private static final int THREADS = Math.max(2, Runtime.getRuntime().availableProcessors());

    private final StreetScene hard = new StreetScene(StreetOptions.HARD);
    private final StreetScene soft = new StreetScene(StreetOptions.soft(LAMP_RADIUS, QUALITY.shadowSamples()));
    private final List<StreetTimings.Row> rows = new ArrayList<>();

    private Camera plain, plainOneThread, plainSmall, plainNoBvh, antiAliased, softShadows, adaptiveShadows;
    private Camera adaptiveShadowsOneThread, everything;

    private SamplingConfig antiAliasing() {
        return new SamplingConfig(QUALITY.aaSamples(), TargetShape.RECTANGLE, SamplingPattern.GRID);
    }

    private static RenderSettings adaptiveShadowSettings() {
        return RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true);
    }

    @BeforeAll
    void renderEveryVariant() {
        StreetTimings.recordLoad();
        // Warm-up, not timed: lets the JIT compile the tracing paths (hard and soft shadows, anti-aliasing) before
        // the first measured render, which is the baseline of every speed-up.
        hard.camera(QUALITY.width(), QUALITY.height()).build().renderImage();
        new StreetScene(StreetOptions.soft(LAMP_RADIUS, 4))
                .camera(QUALITY.width() / 4, QUALITY.height() / 4)
                .setSamplingConfig(new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.GRID))
                .build()
                .renderImage();

        int w = QUALITY.width(), h = QUALITY.height();
        String aa = "anti-aliasing " + QUALITY.aaSamples() + " (GRID)";
        String shadows = "soft shadows " + QUALITY.shadowSamples() + "/lamp";
        plain = render(
                "plain: hard shadows, no anti-aliasing, BVH, " + THREADS + " threads", "street", hard, w, h, c -> {});
        plainOneThread = render("plain, 1 thread", "street-1thread", hard, w, h, c -> c.setThreads(1));
        if (QUALITY.bvhOffWidth() == w) {
            plainSmall = plain;
        } else {
            plainSmall = render(
                    "plain (smaller image)",
                    "street-small",
                    hard,
                    QUALITY.bvhOffWidth(),
                    QUALITY.bvhOffHeight(),
                    c -> {});
        }
        plainNoBvh = render(
                "plain, BVH off (brute force)",
                "street-nobvh",
                hard,
                QUALITY.bvhOffWidth(),
                QUALITY.bvhOffHeight(),
                c -> c.setBvh(false));
        antiAliased = render(aa, "street-aa", hard, w, h, c -> c.setSamplingConfig(antiAliasing()));
        softShadows = render(shadows, "street-soft", soft, w, h, c -> {});
        adaptiveShadows = render(
                shadows + ", adaptive",
                "street-soft-adaptive",
                soft,
                w,
                h,
                c -> c.setRenderSettings(adaptiveShadowSettings()));
        adaptiveShadowsOneThread = render(
                shadows + ", adaptive, 1 thread",
                "street-soft-adaptive-1thread",
                soft,
                w,
                h,
                c -> c.setRenderSettings(adaptiveShadowSettings()).setThreads(1));
        everything = render(
                aa + " adaptive + " + shadows + " adaptive: every feature on",
                "street2",
                soft,
                w,
                h,
                c -> c.setSamplingConfig(antiAliasing().adaptive(StreetScene.ADAPTIVE_THRESHOLD))
                        .setRenderSettings(adaptiveShadowSettings()));
        rows.add(StreetTimings.estimate(
                aa + " + " + shadows + ", neither adaptive (estimate: " + QUALITY.aaSamples()
                        + " x the soft-shadow render, not rendered)",
                rowOf(softShadows),
                QUALITY.aaSamples()));
    }

    /**
     * Renders a variant (repeated when cheap, all runs checked bit-identical), writes its image and records its
     * timing row.
     */
    private Camera render(
            String label, String file, StreetScene street, int width, int height, Consumer<Camera> setup) {
        double[] seconds = new double[3], cpuSeconds = new double[3];
        Camera first = null;
        int runs = 0;
        do {
            Camera camera = street.camera(width, height).setThreads(THREADS).build();
            setup.accept(camera);
            long cpu = StreetTimings.processCpuNanos();
            camera.renderImage();
            cpuSeconds[runs] = (StreetTimings.processCpuNanos() - cpu) * 1e-9;
            seconds[runs++] = camera.getLastStatistics().wallSeconds();
            if (first == null) {
                first = camera;
            } else {
                assertNull(
                        FeatureScenes.firstDifference(first.getImage(), camera.getImage()),
                        label + ": a repeated render differs");
            }
        } while (runs < 3 && seconds[0] < QUALITY.cheapSeconds());
        first.writeToImage(file);
        double wall = StreetTimings.median(seconds, runs), cpu = StreetTimings.median(cpuSeconds, runs);
        rows.add(new StreetTimings.Row(
                label, file + ".png", width, height, wall, cpu, runs, first.getLastStatistics(), false));
        System.out.printf("%s: %.2f s, %.2f CPU s (%d run(s))%n", label, wall, cpu, runs);
        return first;
    }

    private StreetTimings.Row rowOf(Camera camera) {
        for (StreetTimings.Row row : rows) if (row.statistics() == camera.getLastStatistics()) return row;
        throw new IllegalStateException("no row for this render");
    }

    @AfterAll
    void writeTimings() {
        StreetTimings.recordLoad();
        String table = StreetTimings.markdown(QUALITY, hard, rows);
        System.out.println(table);
        StreetTimings.write(table);
    }

    // ------------------------------------------------------------------ determinism

    @Test
    void bvhOnAndOffGiveBitIdenticalImages() {
        assertNull(FeatureScenes.firstDifference(plainSmall.getImage(), plainNoBvh.getImage()));
        assertTrue(plainNoBvh.getLastStatistics().nodeVisits() == 0, "brute force visits no BVH node");
        assertTrue(plainSmall.getLastStatistics().nodeVisits() > 0, "the BVH render searched the tree");
    }

    @Test
    void oneAndAllThreadsGiveBitIdenticalImages() {
        assertEquals(THREADS, plain.getLastStatistics().threads());
        assertEquals(1, plainOneThread.getLastStatistics().threads());
        assertNull(FeatureScenes.firstDifference(plain.getImage(), plainOneThread.getImage()));
        // With random shadow samples and adaptive probes too: every stream is seeded by pixel and light.
        assertNull(FeatureScenes.firstDifference(adaptiveShadows.getImage(), adaptiveShadowsOneThread.getImage()));
    }

    // ------------------------------------------------------------------ where the features change pixels

    @Test
    void softShadowsChangePixelsOnlyInPenumbrae() {
        ImageWriter hardImage = plain.getImage(), softImage = softShadows.getImage();
        boolean[][] changed = ImageMaps.changed(hardImage, softImage, 0);
        int nx = hardImage.getNx(), ny = hardImage.getNy();
        PenumbraProbe probe = new PenumbraProbe(soft.scene(), softShadows);
        Boolean[][] quick = new Boolean[ny][nx], dense = new Boolean[ny][nx];
        int count = 0, faint = 0, outside = 0;
        String firstOutside = null;
        for (int y = 0; y < ny; y++) {
            for (int x = 0; x < nx; x++) {
                if (!changed[y][x]) continue;
                count++;
                // One pixel of slack: a sliver of penumbra that a tracer sample caught but no probe did lies next
                // to pixels the probes do see in the penumbra. The dense probe is slow: only where the quick fails.
                if (nearPenumbra(probe, quick, x, y, false)) continue;
                if (nearPenumbra(probe, dense, x, y, true)) {
                    faint++;
                } else {
                    outside++;
                    if (firstOutside == null) firstOutside = x + "," + y;
                }
            }
        }
        System.out.printf(
                "soft shadows changed %d of %d pixels: %d in faint penumbrae only the dense probe finds, %d elsewhere%n",
                count, nx * ny, faint, outside);
        assertEquals(0, outside, "pixels changed away from any penumbra, first at " + firstOutside);
        // The feature must do something visible: the lamps' penumbrae cover a good part of the picture.
        assertTrue(count > nx * ny / 100, "soft shadows changed only " + count + " pixels");
        assertTrue(ImageMaps.count(ImageMaps.changed(hardImage, softImage, 8)) > nx * ny / 500, "visibly");
    }

    /** Whether pixel (x, y) or one of its 8 neighbours is penumbral (answers cached in {@code known}). */
    private static boolean nearPenumbra(PenumbraProbe probe, Boolean[][] known, int x, int y, boolean dense) {
        for (int qy = Math.max(0, y - 1); qy <= Math.min(known.length - 1, y + 1); qy++) {
            for (int qx = Math.max(0, x - 1); qx <= Math.min(known[0].length - 1, x + 1); qx++) {
                if (known[qy][qx] == null) known[qy][qx] = probe.penumbral(qx, qy, dense);
                if (known[qy][qx]) return true;
            }
        }
        return false;
    }

    @Test
    void antiAliasingChangesPixelsOnlyNearEdges() {
        ImageWriter sharp = plain.getImage(), smooth = antiAliased.getImage();
        int nx = sharp.getNx(), ny = sharp.getNy();
        int k = (int) Math.round(Math.sqrt(QUALITY.aaSamples()));
        assertEquals(
                (long) QUALITY.aaSamples() * nx * ny,
                antiAliased.getLastStatistics().rays().camera,
                "every pixel fires the full GRID of camera rays");
        // Stated tolerance: changes up to 2 (of 255) come from averaging smooth shading over the pixel. Larger ones
        // need an edge: next to the pixel in the sharp image (a neighbour differing by more than 2), or inside it,
        // found by tracing the GRID's own rays, for a feature thinner than a pixel that every pixel centre missed.
        boolean[][] changed = changedOnScreen(sharp, smooth, 2);
        boolean[][] nearEdges = ImageMaps.dilate(ImageMaps.edges(sharp, 2), 1);
        EdgeProbe probe = new EdgeProbe(hard.scene(), plain);
        int count = 0, inside = 0, outside = 0;
        String firstOutside = null;
        for (int y = 0; y < ny; y++) {
            for (int x = 0; x < nx; x++) {
                if (!changed[y][x]) continue;
                count++;
                if (nearEdges[y][x]) continue;
                if (probe.edgeInside(x, y, k)) {
                    inside++;
                } else {
                    outside++;
                    if (firstOutside == null) firstOutside = x + "," + y;
                }
            }
        }
        System.out.printf(
                "anti-aliasing changed %d of %d pixels: %d near edges of the sharp image, %d at edges inside the"
                        + " pixel that it missed, %d elsewhere%n",
                count, nx * ny, count - inside - outside, inside, outside);
        assertEquals(0, outside, "pixels changed away from any edge, first at " + firstOutside);
        // And it does smooth the edges: most high-contrast edge pixels take a blended colour.
        boolean[][] strong = ImageMaps.edges(sharp, 40);
        int strongCount = 0, smoothed = 0;
        for (int y = 0; y < ny; y++) {
            for (int x = 0; x < nx; x++) {
                if (!strong[y][x]) continue;
                strongCount++;
                if (changed[y][x]) smoothed++;
            }
        }
        assertTrue(smoothed > strongCount / 2, smoothed + " of " + strongCount + " strong edge pixels smoothed");
    }

    private static boolean[][] changedOnScreen(ImageWriter a, ImageWriter b, double tolerance) {
        boolean[][] map = new boolean[a.getNy()][a.getNx()];
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                Color p = ImageMaps.clamp(a.getPixel(x, y)), q = ImageMaps.clamp(b.getPixel(x, y));
                map[y][x] = ImageMaps.channelDifference(p, q) > tolerance;
            }
        }
        return map;
    }

    // ------------------------------------------------------------------ landmarks

    @Test
    void litWindowsAndLampHeadsAreBright() {
        for (Camera camera : List.of(plain, everything)) {
            boolean sharp = camera.getSamplingConfig().getSampleCount() == 1;
            double quartile = brightnessPercentile(camera.getImage(), 0.75);
            int windows = checkBright(camera, hard.litWindows(), quartile);
            int lamps = checkBright(camera, hard.lampGlobes(), 200);
            System.out.printf(
                    "%d lit windows (brighter than 3/4 of the picture, %.1f) and %d lamp globes (over 200) checked%n",
                    windows, quartile, lamps);
            // Anti-aliased, only windows and globes covering a 3 x 3 block of pixels count: few do in the preview.
            assertTrue(windows >= (sharp ? 30 : 10), "only " + windows + " lit windows could be checked");
            assertTrue(lamps >= (sharp ? 8 : 4), "only " + lamps + " lamp globes could be checked");
        }
    }

    /**
     * Checks every landmark whose point projects into the image and is what the camera sees there: the pixel is
     * at least {@code minimum} bright and, without anti-aliasing, at least as bright as the landmark's own emission
     * (shading only adds to it), comparing channel means after clamping. Returns how many were checked.
     *
     * <p>"What the camera sees there" is decided by tracing the pixel's central ray; with anti-aliasing the rays
     * of the 8 neighbouring pixels must hit the landmark too, so the whole pixel (whose samples lie inside the
     * neighbours' centres) shows it and not a blend with its frame.
     */
    private int checkBright(Camera camera, List<Landmark> landmarks, double minimum) {
        Accelerator scene = Accelerator.build(hard.scene().geometries, true);
        int radius = camera.getSamplingConfig().getSampleCount() == 1 ? 0 : 1;
        int checked = 0;
        for (Landmark landmark : landmarks) {
            int[] pixel = pixelOf(landmark.point(), camera.getNx(), camera.getNy());
            if (pixel == null || !covers(camera, scene, landmark, pixel, radius)) {
                continue; // out of the picture, hidden behind a tree or a lamp, or too small to cover the pixel
            }
            Color c = ImageMaps.clamp(camera.getImage().getPixel(pixel[0], pixel[1]));
            double brightness = FeatureScenes.brightness(c);
            // One sharp ray sees the emission plus shading; anti-aliased samples may also catch a glazing bar
            // thinner than the gaps between the rays checked, so there only the minimum applies.
            double emission = radius == 0
                    ? FeatureScenes.brightness(
                                    ImageMaps.clamp(landmark.surface().getEmission()))
                            - 1e-9
                    : 0;
            assertTrue(
                    brightness >= Math.max(minimum, emission),
                    "landmark at " + landmark.point() + " (pixel " + pixel[0] + "," + pixel[1] + ") is only "
                            + brightness + " bright: " + c + "; its emission is " + emission + ", the minimum "
                            + minimum);
            checked++;
        }
        return checked;
    }

    /** Whether the central rays of the pixels within {@code radius} of {@code pixel} all hit the landmark. */
    private static boolean covers(Camera camera, Accelerator scene, Landmark landmark, int[] pixel, int radius) {
        int nx = camera.getNx(), ny = camera.getNy();
        for (int y = pixel[1] - radius; y <= pixel[1] + radius; y++) {
            for (int x = pixel[0] - radius; x <= pixel[0] + radius; x++) {
                if (x < 0 || y < 0 || x >= nx || y >= ny) return false;
                HitRecord hit = new HitRecord();
                Ray ray = camera.constructRay(nx, ny, x, y);
                if (!scene.intersect(ray, 0, Double.POSITIVE_INFINITY, hit) || hit.geometry != landmark.surface()) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The brightness (channel mean after clamping) that the given fraction of the pixels do not exceed. */
    private static double brightnessPercentile(ImageWriter image, double fraction) {
        double[] values = new double[image.getNx() * image.getNy()];
        for (int y = 0, i = 0; y < image.getNy(); y++) {
            for (int x = 0; x < image.getNx(); x++) {
                values[i++] = FeatureScenes.brightness(ImageMaps.clamp(image.getPixel(x, y)));
            }
        }
        Arrays.sort(values);
        return values[(int) (fraction * (values.length - 1))];
    }

    @Test
    void theMoonIsWhereItShouldBe() {
        Sphere moon = hard.moon();
        for (Camera camera : List.of(plain, everything)) {
            int nx = camera.getNx(), ny = camera.getNy();
            int[] centre = pixelOf(moon.getCenter(), nx, ny);
            assertTrue(centre != null, "the moon is in the picture");
            // It rises over the far end of the street: in the upper half, near the middle.
            assertTrue(
                    centre[1] < ny / 2 && Math.abs(centre[0] - nx / 2) < nx / 5, "moon at " + Arrays.toString(centre));
            ImageWriter image = camera.getImage();
            assertTrue(
                    ImageMaps.channelDifference(image.getPixel(centre[0], centre[1]), moon.getEmission()) < 1e-9,
                    "the moon's centre pixel has the moon's colour: " + image.getPixel(centre[0], centre[1]));
            // Its disk has the projected radius: moonlight (the moon's face or one of its greyer maria) up to it,
            // night sky beyond.
            double radius = projectedRadius(moon, nx);
            assertTrue(radius > 2, "the moon is a disk, radius " + radius + " pixels");
            // Stated tolerance: 10% and a pixel either way (the disk is stretched a few percent off the axis).
            int inside = (int) Math.floor(0.9 * radius - 1), outside = (int) Math.ceil(1.1 * radius + 1);
            for (int[] d : new int[][] {{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                Color in = image.getPixel(centre[0] + d[0] * inside, centre[1] + d[1] * inside);
                Color out = image.getPixel(centre[0] + d[0] * outside, centre[1] + d[1] * outside);
                assertTrue(FeatureScenes.brightness(in) > 180, "inside the disk it is bright: " + in);
                assertTrue(FeatureScenes.brightness(out) < 40, "outside the disk the sky is dark: " + out);
            }
        }
    }

    // ------------------------------------------------------------------ the scene itself

    @Test
    void theSceneHasWhatTheIssueAsksFor() {
        int primitives = hard.primitiveCount();
        System.out.println("street scene: " + primitives + " primitives");
        assertTrue(primitives >= 1000, primitives + " primitives");
        assertTrue(countMeshes(hard.scene().geometries) >= 1, "a triangle mesh");
        int lamps = 0, spots = 0, directional = 0;
        for (LightSource light : soft.scene().lights) {
            if (light instanceof SpotLight) spots++;
            else if (light instanceof PointLight lamp) {
                lamps++;
                assertEquals(LAMP_RADIUS, lamp.getRadius());
                assertEquals(QUALITY.shadowSamples(), lamp.getNumSamples());
            } else if (light instanceof DirectionalLight) directional++;
        }
        assertTrue(lamps >= 8, lamps + " street lamps");
        assertEquals(1, spots);
        assertEquals(1, directional);
        assertTrue(!hard.scene().ambientLight.getIntensity().isBlack(), "ambient light");
        RayCounters rays = plain.getLastStatistics().rays();
        assertTrue(
                rays.reflection > 0 && rays.refraction > 0,
                "wet road and glass: " + rays.reflection + ", " + rays.refraction);
    }

    private static int countMeshes(Intersectable g) {
        if (g instanceof Mesh) return 1;
        if (!(g instanceof Geometries composite)) return 0;
        int n = 0;
        for (Intersectable member : composite.getMembers()) n += countMeshes(member);
        return n;
    }

    // ------------------------------------------------------------------ projection

    /**
     * The pixel (column, row) whose centre is nearest the projection of {@code p}, computed from the camera's
     * defining constants (not through {@link Camera}), or null if it falls outside the image or behind the camera.
     */
    static int[] pixelOf(Point p, int nx, int ny) {
        double[] uv = viewPlane(p);
        if (uv == null) return null;
        double pixel = StreetScene.VP_WIDTH / nx;
        int column = (int) Math.round(uv[0] / pixel + (nx - 1) / 2.0);
        int row = (int) Math.round((ny - 1) / 2.0 - uv[1] / pixel);
        return column < 0 || row < 0 || column >= nx || row >= ny ? null : new int[] {column, row};
    }

    /** View-plane coordinates (right, up) of the point, or null behind the camera. */
    private static double[] viewPlane(Point p) {
        Vector to =
                StreetScene.CAMERA_TARGET.subtract(StreetScene.CAMERA_LOCATION).normalize();
        Vector right = to.crossProduct(Vector.AXIS_Z).normalize();
        Vector up = right.crossProduct(to);
        Vector d = p.subtract(StreetScene.CAMERA_LOCATION);
        double depth = d.dotProduct(to);
        if (depth <= 0) return null;
        double scale = StreetScene.VP_DISTANCE / depth;
        return new double[] {d.dotProduct(right) * scale, d.dotProduct(up) * scale};
    }

    /** Radius in pixels of the sphere's image (small-angle: its radius over its distance, on the view plane). */
    private static double projectedRadius(Sphere sphere, int nx) {
        Vector to =
                StreetScene.CAMERA_TARGET.subtract(StreetScene.CAMERA_LOCATION).normalize();
        double depth = sphere.getCenter().subtract(StreetScene.CAMERA_LOCATION).dotProduct(to);
        return sphere.getRadius() * StreetScene.VP_DISTANCE / depth / (StreetScene.VP_WIDTH / nx);
    }
}
