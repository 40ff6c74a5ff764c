package distributed;

import cli.BadInputException;
import cli.ExitCodes;
import cli.OutputFile;
import cli.RenderOverrides;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.apache.spark.api.java.JavaSparkContext;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import renderer.ImageWriter;

/**
 * {@code raytracer-spark tiles scene.json [--tiles 4x4] [-o out.png] [--master URL] [--width W] [--height H]
 * [--samples N] [--bvh on|off]}: renders a still image as tiles on Spark and writes the stitched PNG. The scene
 * file (with the overrides, as {@code raytracer render} applies them) and the output are checked before Spark
 * starts.
 */
@Command(
        name = "tiles",
        mixinStandardHelpOptions = true,
        description = "Renders a scene file as tiles on Spark (one task per tile) and stitches them into one PNG.",
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:the image was written",
            "1:the render or writing the image failed",
            "2:bad input: scene file, option or output path (nothing rendered)"
        })
public final class TilesCommand implements Callable<Integer> {
    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "<scene.json>", description = "the scene file (docs/SCENE-FORMAT.md)")
    private Path sceneFile;

    @Option(
            names = {"-o", "--output"},
            paramLabel = "<out.png>",
            description = "the image to write (default: images/<scene name>.png; its folder must exist)")
    private Path output;

    @Option(
            names = "--tiles",
            paramLabel = "COLSxROWS|N",
            defaultValue = "4x4",
            description = "the tiles, one Spark task each: a grid such as 4x4, or a count (default: ${DEFAULT-VALUE})")
    private String tiles;

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
        PrintWriter err = spec.commandLine().getErr();
        TileGrid grid;
        try {
            grid = TileGrid.parse(tiles);
        } catch (IllegalArgumentException e) {
            throw new BadInputException(e.getMessage());
        }
        overrides.check();
        SceneBundle bundle = SceneBundle.read(sceneFile, overrides); // a bad scene fails here, before Spark starts
        List<Tile> split;
        try {
            split = grid.split(bundle.width(), bundle.height());
        } catch (IllegalArgumentException e) {
            throw new BadInputException("--tiles " + tiles + ": " + e.getMessage());
        }
        Path target = output != null
                ? OutputFile.check(output, false)
                : OutputFile.check(Path.of("images", bundle.sceneName() + ".png"), true);
        boolean existed = Files.exists(target);

        long start = System.nanoTime();
        FailedAttempts failed = new FailedAttempts();
        double seconds;
        String master;
        int cores;
        try (JavaSparkContext spark = SparkContexts.open(this.master)) {
            spark.sc().addSparkListener(failed);
            master = spark.master();
            cores = spark.defaultParallelism();
            long jobStart = System.nanoTime();
            ImageWriter image = SparkTileRender.render(spark, bundle, split, FaultInjection.from(spark.getConf()));
            seconds = (System.nanoTime() - jobStart) * 1e-9;
            image.writeToImage(target);
        } catch (RuntimeException | Error e) {
            err.println("render failed: no image written" + (existed ? "; " + target + " was left unchanged" : ""));
            throw e;
        }
        // After the context stopped, so every task event has been counted.
        out.println("wrote " + target);
        out.printf(
                Locale.ROOT,
                "spark: %d tiles (%s) rendered in %.3f s on %s (%d cores), %d failed task attempts retried;"
                        + " %.3f s with Spark's start and stop%n",
                split.size(),
                grid,
                seconds,
                master,
                cores,
                failed.count(),
                (System.nanoTime() - start) * 1e-9);
        out.flush();
        return ExitCodes.OK;
    }
}
