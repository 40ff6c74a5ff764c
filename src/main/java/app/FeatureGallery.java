package app;

import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.Supplier;
import javax.imageio.ImageIO;
import renderer.Camera;
import renderer.RenderSettings;
import renderer.RenderStatistics;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/**
 * Renders the showcase scene with each sampled effect off and on, writes side-by-side pictures
 * ({@code images/features-*.png}) and prints what each effect costs in time: the median of repeated renders,
 * and the factor over the same render with the effect off.
 *
 * <p>Run: {@code mvn -q compile exec:java -Dexec.mainClass=app.FeatureGallery [-Dexec.args="runs width height"]}.
 */
public final class FeatureGallery {
    private FeatureGallery() {}

    /**
     * Renders the effect pictures and prints the cost table.
     *
     * @param args optionally {@code runs width height}: timed runs per figure (1 to 1000, default 3) and image size
     *     (default 400 x 250)
     * @throws IllegalArgumentException if the run count or the size is out of range
     */
    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 3;
        int width = args.length > 1 ? Integer.parseInt(args[1]) : 400;
        int height = args.length > 2 ? Integer.parseInt(args[2]) : 250;
        if (runs < 1 || runs > 1000) throw new IllegalArgumentException("runs must be in [1, 1000], but was " + runs);
        if (width < 1 || height < 1 || (long) width * height > 1L << 24) {
            throw new IllegalArgumentException("width and height must be at least 1 and hold at most 2^24 pixels, but"
                    + " were " + width + " x " + height);
        }
        System.out.printf(
                Locale.ROOT,
                "Showcase scene, %d x %d, %d thread(s), median of %d runs%n%n",
                width,
                height,
                Runtime.getRuntime().availableProcessors(),
                runs);
        System.out.println("| effect | off (s) | on (s) | time factor | rays off | rays on |");
        System.out.println("|---|---:|---:|---:|---:|---:|");
        SamplingConfig aa = new SamplingConfig(16, TargetShape.RECTANGLE, SamplingPattern.JITTERED);
        for (int i = 0; i < 3; i++)
            Showcase.camera(Showcase.scene(true, 0.08), width, height).build().renderImage();
        compare(
                "aa",
                "anti-aliasing (16 jittered samples per pixel)",
                runs,
                () -> Showcase.camera(Showcase.scene(false, 0), width, height).build(),
                () -> Showcase.camera(Showcase.scene(false, 0), width, height)
                        .setSamplingConfig(aa)
                        .build());
        compare(
                "soft-shadows",
                "soft shadows (2 disk lights, 16 shadow rays each)",
                runs,
                () -> Showcase.camera(Showcase.scene(false, 0), width, height).build(),
                () -> Showcase.camera(Showcase.scene(true, 0), width, height).build());
        compare(
                "adaptive-shadows",
                "soft shadows, adaptive (rim probes first)",
                runs,
                () -> Showcase.camera(Showcase.scene(false, 0), width, height).build(),
                () -> Showcase.camera(Showcase.scene(true, 0), width, height)
                        .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true))
                        .build());
        compare(
                "dof",
                "depth of field (aperture 6, 16 lens samples)",
                runs,
                () -> Showcase.camera(Showcase.scene(false, 0), width, height).build(),
                () -> Showcase.camera(Showcase.scene(false, 0), width, height)
                        .setDepthOfField(430, 6)
                        .build());
        compare(
                "glossy",
                "glossy floor (roughness 0.08, 16 rays)",
                runs,
                () -> Showcase.camera(Showcase.scene(false, 0), width, height).build(),
                () -> Showcase.camera(Showcase.scene(false, 0.08), width, height)
                        .build());
    }

    /** Renders both variants {@code runs} times, prints a table row, writes the side-by-side picture. */
    private static void compare(String file, String effect, int runs, Supplier<Camera> off, Supplier<Camera> on) {
        Timed a = time(off, runs), b = time(on, runs);
        System.out.printf(
                Locale.ROOT,
                "| %s | %.2f | %.2f | %.1fx | %,d | %,d |%n",
                effect,
                a.seconds,
                b.seconds,
                b.seconds / a.seconds,
                a.stats.rays().total(),
                b.stats.rays().total());
        writeSideBySide(
                a.camera.getImage().toBufferedImage(),
                b.camera.getImage().toBufferedImage(),
                Path.of("images", "features-" + file + ".png"),
                effect);
    }

    private record Timed(Camera camera, double seconds, RenderStatistics stats) {}

    private static Timed time(Supplier<Camera> cameras, int runs) {
        cameras.get().renderImage(); // warm-up: let the JIT compile the paths this variant uses
        double[] seconds = new double[runs];
        Camera camera = null;
        for (int i = 0; i < runs; i++) {
            camera = cameras.get().renderImage();
            seconds[i] = camera.getLastStatistics().wallSeconds();
        }
        Arrays.sort(seconds);
        return new Timed(camera, seconds[runs / 2], camera.getLastStatistics());
    }

    private static void writeSideBySide(BufferedImage left, BufferedImage right, Path file, String caption) {
        int w = left.getWidth(), h = left.getHeight(), gap = 6, band = 22;
        BufferedImage out = new BufferedImage(2 * w + gap, h + band, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(java.awt.Color.WHITE);
        g.fillRect(0, 0, out.getWidth(), out.getHeight());
        g.drawImage(left, 0, band, null);
        g.drawImage(right, w + gap, band, null);
        g.setColor(java.awt.Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        g.drawString("off", 6, 16);
        g.drawString("on: " + caption, w + gap + 6, 16);
        g.dispose();
        renderer.AtomicFile.write(file, "image", temp -> ImageIO.write(out, "png", temp.toFile()));
    }
}
