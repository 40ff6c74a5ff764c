package benchmark;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import launch.JavaLaunch;
import renderer.Camera;
import renderer.ProgressiveSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import sceneio.LoadedScene;
import sceneio.SceneLoader;

/**
 * The soft-shadow comparison with POV-Ray 3.7 of docs/ACCURACY.md: {@code scenes/povray/soft-shadow.pov} and
 * {@code .json}, 256 x 256, one camera ray per pixel, one thread. POV-Ray renders its adaptive, jittered circular
 * area light at 3x3 to 17x17 lights (its own "Trace Time" and shadow-ray count) and a converged 33x33 reference; this
 * library renders to RMSEs 4, 2 and 1 with progressive sampling (the target asked lowered in 2% steps until the 8-bit
 * image's measured error reaches the one wanted), timed as its command line prints it (a new
 * JVM per render), through {@code --daemon} (the render daemon's first render and later ones, with the client's time
 * from start to exit, beside POV-Ray's) and in a warm JVM (median of 5), and a converged reference (4,096 shadow
 * rays per pixel). Each renderer is measured against its own reference, on the 8-bit images. Needs {@code povray}
 * on the PATH; {@code raytracer benchmark povray [output folder]}.
 */
public final class PovRayComparison {
    private static final Path SCENE = Path.of("scenes/povray/soft-shadow.json");
    private static final Path POV = Path.of("scenes/povray/soft-shadow.pov");
    private static final double[] TARGETS = {4, 2, 1};
    private static final int[] POV_LIGHTS = {3, 5, 9, 17};
    private static final int DAEMON_RUNS = 5;
    private static final Pattern RENDER_TIME = Pattern.compile("render: ([0-9.]+) s wall \\(([0-9.]+) s preparing\\)");

    private PovRayComparison() {}

    /**
     * Runs the comparison and prints Markdown tables.
     *
     * @param args optionally the folder for the images (default {@code images/povray})
     * @throws IOException if an image cannot be written or read, or POV-Ray cannot be run
     * @throws InterruptedException if interrupted while POV-Ray runs
     */
    public static void main(String[] args) throws Exception {
        Path out = Path.of(args.length > 0 ? args[0] : "images/povray");
        Files.createDirectories(out);
        System.out.println("POV-Ray (adaptive 1, jitter, circular orient; 1 thread), against its 33x33 reference:\n");
        BufferedImage povReference = povray(out, 33, -1, 0).image;
        System.out.println(
                "| lights | shadow rays | trace time (s) | from start to exit (s) | RMSE |\n|---:|---:|---:|---:|---:|");
        List<double[]> povCurve = new ArrayList<>();
        List<double[]> povWallCurve = new ArrayList<>();
        for (int n : POV_LIGHTS) {
            PovRun r = povray(out, n, 1, 1);
            double error = rmse(r.image, povReference);
            povCurve.add(new double[] {r.seconds, error});
            povWallCurve.add(new double[] {r.wall, error});
            System.out.printf(
                    Locale.ROOT,
                    "| %dx%d | %,d | %.3f | %.3f | %.3f |%n",
                    n,
                    n,
                    r.shadowRays,
                    r.seconds,
                    r.wall,
                    error);
        }
        BufferedImage reference = referenceImage(out);
        System.out.println(
                "\nThis library (progressive, 2 shadow rays per sample; 1 thread), against its reference:\n");
        System.out.println(
                "| RMSE to reach | target asked | measured RMSE | predicted | shadow rays | command-line time (s) |"
                        + " of which preparing (s) | warm JVM (s) | POV-Ray's time to that error (s) |"
                        + "\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        List<String> daemonRows = new ArrayList<>();
        for (double target : TARGETS) {
            double asked = targetAskedFor(target, reference);
            DaemonTimes daemon = daemonSeconds(asked, out);
            CommandLineTime cli = commandLineSeconds(asked, out);
            double[] warm = new double[5];
            Camera camera = null;
            for (int i = -1; i < warm.length; i++) { // one warm-up render
                camera = progressive(asked).renderImage();
                if (i >= 0) warm[i] = camera.getLastStatistics().wallSeconds();
            }
            Arrays.sort(warm);
            double error = rmse(camera.getImage().toBufferedImage(), reference);
            System.out.printf(
                    Locale.ROOT,
                    "| %.0f | %.3f | %.3f | %.3f | %,d | %.3f | %.3f | %.3f | %s |%n",
                    target,
                    asked,
                    error,
                    camera.getLastProgressiveReport().predictedError(),
                    camera.getLastStatistics().rays().shadow,
                    cli.render(),
                    cli.preparing(),
                    warm[warm.length / 2],
                    timeTo(povCurve, error));
            daemonRows.add(String.format(
                    Locale.ROOT,
                    "| %.0f | %.3f | %.3f | %.3f | %.3f | %s | %s |",
                    target,
                    cli.wall(),
                    daemon.first(),
                    daemon.render(),
                    daemon.wall(),
                    timeTo(povCurve, error),
                    timeTo(povWallCurve, error)));
        }
        System.out.println("\nThe command line with --daemon (the same renders; the daemon started afresh for each"
                + " error, its first render, then the median of " + DAEMON_RUNS + " more):\n");
        System.out.println("| RMSE to reach | without the daemon, from start to exit (s) | daemon's first render (s)"
                + " | later renders (s) | client from start to exit (s) | POV-Ray's time to that error (s)"
                + " | POV-Ray from start to exit (s) |\n|---:|---:|---:|---:|---:|---:|---:|");
        daemonRows.forEach(System.out::println);
    }

    /**
     * The target to ask for an 8-bit image within {@code wanted} of the reference: the error is measured on 8-bit
     * images, whose rounding adds to it where a pixel's noise is small, so the target is lowered by 2% at a time
     * (at most twenty times) until the measured error reaches the one wanted.
     */
    private static double targetAskedFor(double wanted, BufferedImage reference) throws Exception {
        double asked = wanted;
        for (int step = 0; step < 20; step++) {
            BufferedImage image = progressive(asked).renderImage().getImage().toBufferedImage();
            if (rmse(image, reference) <= wanted) break;
            asked *= 0.98;
        }
        return asked;
    }

    private static Camera progressive(double target) throws Exception {
        LoadedScene scene = SceneLoader.load(SCENE);
        return scene.camera().setThreads(1).setProgressive(ProgressiveSettings.targetError(target));
    }

    /** 4,096 HALTON shadow rays per pixel in one beam, on every core. */
    private static BufferedImage referenceImage(Path out) throws Exception {
        String json =
                Files.readString(SCENE, StandardCharsets.UTF_8).replace("\"samples\": 2 }", "\"samples\": 4096 }");
        Camera camera =
                SceneLoader.load(json, SCENE.toString(), SCENE.getParent()).camera();
        camera.setThreads(Runtime.getRuntime().availableProcessors())
                .setRenderSettings(camera.getRenderSettings().withShadowSampling(SamplingPattern.HALTON, false))
                .setSamplingConfig(new SamplingConfig(1, TargetShape.RECTANGLE, SamplingPattern.HALTON));
        BufferedImage image = camera.renderImage().getImage().toBufferedImage();
        ImageIO.write(image, "png", out.resolve("ours-reference.png").toFile());
        return image;
    }

    /**
     * The render time the command line prints and the part of it spent preparing the scene (its accelerator and
     * effect plan; POV-Ray prints the like of it apart, as its parse and bounding times, outside its trace time).
     */
    private record CommandLineTime(double render, double preparing, double wall) {}

    /** The render time the command line prints, for a render in a JVM of its own. */
    private static CommandLineTime commandLineSeconds(double target, Path out)
            throws IOException, InterruptedException {
        Run run = commandLine(renderArgs(target, out, false));
        Matcher m = renderTime(run.output());
        return new CommandLineTime(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)), run.wall());
    }

    /** The daemon's first render, the median of the later ones as printed, and their clients' start to exit. */
    private record DaemonTimes(double first, double render, double wall) {}

    /**
     * Renders through {@code --daemon}: the daemon's first render (the daemon stopped before it, so started afresh)
     * and the medians of {@value #DAEMON_RUNS} more, as printed and as the client's time from start to exit.
     */
    private static DaemonTimes daemonSeconds(double target, Path out) throws IOException, InterruptedException {
        commandLine(List.of("--daemon", "stop"));
        double first = printedRender(commandLine(renderArgs(target, out, true)).output());
        double[] render = new double[DAEMON_RUNS];
        double[] wall = new double[DAEMON_RUNS];
        for (int i = 0; i < DAEMON_RUNS; i++) {
            Run run = commandLine(renderArgs(target, out, true));
            render[i] = printedRender(run.output());
            wall[i] = run.wall();
        }
        commandLine(List.of("--daemon", "stop"));
        Arrays.sort(render);
        Arrays.sort(wall);
        return new DaemonTimes(first, render[DAEMON_RUNS / 2], wall[DAEMON_RUNS / 2]);
    }

    private static List<String> renderArgs(double target, Path out, boolean daemon) {
        List<String> args = new ArrayList<>();
        if (daemon) args.add("--daemon");
        args.addAll(List.of(
                "render",
                SCENE.toString(),
                "-o",
                out.resolve(String.format(Locale.ROOT, "ours-%.3f.png", target)).toString(),
                "--threads",
                "1",
                "--target-error",
                String.valueOf(target)));
        return args;
    }

    private static double printedRender(String text) throws IOException {
        return Double.parseDouble(renderTime(text).group(1));
    }

    /** The printed render line's match: group 1 the render's wall time, group 2 the part of it spent preparing. */
    private static Matcher renderTime(String text) throws IOException {
        Matcher m = RENDER_TIME.matcher(text);
        if (!m.find()) throw new IOException("no render time in the command line's output:\n" + text);
        return m;
    }

    /** A command line's output (stdout and stderr) and its time from start to exit. */
    private record Run(String output, double wall) {}

    /** Runs the command line in a JVM of its own ({@link JavaLaunch}: also under {@code mvn exec:java}). */
    private static Run commandLine(List<String> args) throws IOException, InterruptedException {
        long start = System.nanoTime();
        Process p = new ProcessBuilder(JavaLaunch.ofThisProgram().command("cli.RaytracerCli", args))
                .redirectErrorStream(true)
                .start();
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        int code = p.waitFor();
        double wall = (System.nanoTime() - start) * 1e-9;
        if (code != 0) throw new IOException("the command line failed (exit " + code + "):\n" + text);
        return new Run(text, wall);
    }

    /** A POV-Ray render: its image, its printed trace time, its shadow rays, and its time from start to exit. */
    private record PovRun(BufferedImage image, double seconds, long shadowRays, double wall) {}

    private static PovRun povray(Path out, int lights, int adaptive, int jitter)
            throws IOException, InterruptedException {
        Path image = out.resolve("povray-" + lights + (adaptive < 0 ? "-reference" : "") + ".png");
        ProcessBuilder povray = new ProcessBuilder(
                        "povray",
                        "-i" + POV,
                        "+W256",
                        "+H256",
                        "+WT1",
                        "-D",
                        "+FN",
                        "+O" + image,
                        "Declare=N=" + lights,
                        "Declare=A=" + adaptive,
                        "Declare=J=" + jitter,
                        "File_Gamma=1.0")
                .redirectErrorStream(true);
        Process p;
        long start = System.nanoTime();
        try {
            p = povray.start();
        } catch (IOException e) {
            throw new IOException(
                    "POV-Ray 3.7 must be on the PATH as 'povray' (Debian: apt-get install povray): " + e.getMessage(),
                    e);
        }
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.waitFor() != 0) throw new IOException("povray failed:\n" + text);
        double wall = (System.nanoTime() - start) * 1e-9;
        Matcher time = Pattern.compile("Trace Time:.*\\(([0-9.]+) seconds\\)").matcher(text);
        Matcher rays = Pattern.compile("Shadow Ray Tests:\\s+([0-9]+)").matcher(text);
        if (!time.find() || !rays.find()) throw new IOException("no trace time in POV-Ray's output:\n" + text);
        return new PovRun(
                ImageIO.read(image.toFile()), Double.parseDouble(time.group(1)), Long.parseLong(rays.group(1)), wall);
    }

    /** RMSE over pixels and channels of two 8-bit images (0..255 scale). */
    static double rmse(BufferedImage a, BufferedImage b) {
        double sum = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y), q = b.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    double d = ((p >> shift) & 255) - ((q >> shift) & 255);
                    sum += d * d;
                }
            }
        }
        return Math.sqrt(sum / (3.0 * a.getWidth() * a.getHeight()));
    }

    /** POV-Ray's time to reach {@code error}, interpolated log-log on its time-error curve, or a bound. */
    private static String timeTo(List<double[]> curve, double error) {
        for (int i = 1; i < curve.size(); i++) {
            double[] a = curve.get(i - 1), b = curve.get(i);
            if (a[1] >= error && b[1] <= error) {
                double f = Math.log(a[1] / error) / Math.log(a[1] / b[1]);
                return String.format(Locale.ROOT, "%.3f", Math.exp(Math.log(a[0]) + f * Math.log(b[0] / a[0])));
            }
        }
        return curve.get(0)[1] <= error
                ? String.format(Locale.ROOT, "< %.3f", curve.get(0)[0])
                : String.format(Locale.ROOT, "> %.3f", curve.get(curve.size() - 1)[0]);
    }
}
