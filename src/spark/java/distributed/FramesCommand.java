package distributed;

import cli.ExitCodes;
import cli.RenderOverrides;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import org.apache.spark.api.java.JavaSparkContext;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import renderer.AtomicFile;
import sceneio.CameraPath;
import sceneio.CameraPathLoader;

/**
 * {@code raytracer-spark frames scene.json --path path.json [-o frames/x-%04d.png] [--master URL] [--width W]
 * [--height H] [--samples N] [--bvh on|off]}: renders every frame of a camera path on Spark, one task per frame,
 * and writes numbered PNGs as the frames arrive. The scene (with the overrides), the path (every pose) and the
 * output are checked before Spark starts.
 */
@Command(
        name = "frames",
        mixinStandardHelpOptions = true,
        description = "Renders the frames of a camera path through a scene file on Spark (one task per frame)"
                + " into numbered PNG files.",
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:every frame was written",
            "1:the render or writing a frame failed (frames already written are complete)",
            "2:bad input: scene file, path file, option or output path (nothing rendered)"
        })
public final class FramesCommand implements Callable<Integer> {
    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "<scene.json>", description = "the scene file (docs/SCENE-FORMAT.md)")
    private Path sceneFile;

    @Option(
            names = "--path",
            required = true,
            paramLabel = "<path.json>",
            description = "the camera path: keyframed location and target (docs/SPARK.md)")
    private Path pathFile;

    @Option(
            names = {"-o", "--output"},
            paramLabel = "<pattern>",
            description = "the frames' files, with one %%d or %%04d for the frame number"
                    + " (default: images/<scene name>-%%04d.png; the folder must exist)")
    private String output;

    @Mixin
    private RenderOverrides overrides = new RenderOverrides();

    @Option(
            names = "--master",
            paramLabel = "URL",
            description = "the Spark master, e.g. local[2,4]; default: spark-submit's --master (spark.master)")
    private String master;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        overrides.check();
        SceneBundle bundle = SceneBundle.read(sceneFile, overrides); // a bad scene fails here, before Spark starts
        CameraPath path = CameraPathLoader.load(pathFile, bundle.document());
        FramePattern files = output != null
                ? FramePattern.check(output, path.frameCount(), false)
                : FramePattern.check("images/" + bundle.sceneName() + "-%04d.png", path.frameCount(), true);

        long start = System.nanoTime();
        AtomicInteger written = new AtomicInteger();
        FailedAttempts failed = new FailedAttempts();
        double seconds;
        String master;
        int cores;
        try (JavaSparkContext spark = SparkContexts.open(this.master)) {
            spark.sc().addSparkListener(failed);
            master = spark.master();
            cores = spark.defaultParallelism();
            long jobStart = System.nanoTime();
            SparkFrameRender.render(
                    spark,
                    bundle,
                    path,
                    (frame, png) -> {
                        AtomicFile.write(files.file(frame), "frame", temp -> Files.write(temp, png));
                        written.incrementAndGet();
                    },
                    FaultInjection.from(spark.getConf()));
            seconds = (System.nanoTime() - jobStart) * 1e-9;
        } catch (RuntimeException | Error e) {
            spec.commandLine()
                    .getErr()
                    .println("render failed after writing " + written.get() + " of " + path.frameCount()
                            + " frames (each written frame is complete)");
            throw e;
        }
        // After the context stopped, so every task event has been counted.
        out.println("wrote " + path.frameCount() + " frames: " + files.file(0) + " .. "
                + files.file(path.frameCount() - 1));
        out.printf(
                Locale.ROOT,
                "spark: %d frames rendered in %.3f s on %s (%d cores), %d failed task attempts retried;"
                        + " %.3f s with Spark's start and stop%n",
                path.frameCount(),
                seconds,
                master,
                cores,
                failed.count(),
                (System.nanoTime() - start) * 1e-9);
        out.flush();
        return ExitCodes.OK;
    }
}
