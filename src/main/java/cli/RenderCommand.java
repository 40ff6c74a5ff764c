package cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import primitives.Limits;
import primitives.Printable;
import renderer.Camera;
import sceneio.LoadedScene;
import sceneio.SceneLoader;
import sceneio.model.RenderDocument;
import sceneio.model.SceneDocument;

/**
 * {@code raytracer render scene.json [-o out.png] [--threads N] [--bvh on|off] [--samples N] [--width W]
 * [--height H]}: loads the scene file, applies the overrides, renders with progress on stderr and writes the PNG.
 *
 * <p>The image is written only after the whole render succeeded, through a temporary file moved into place; on
 * any failure no file is written and an existing file at the output path is left untouched (and the message
 * says so), so an old image is never mistaken for a new result: it keeps its old timestamp.
 */
@Command(
        name = "render",
        mixinStandardHelpOptions = true,
        description = "Renders a JSON scene file into a PNG image.",
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:the image was written",
            "1:the render or writing the image failed",
            "2:bad input: scene file, option or output path (nothing rendered)",
            "130:cancelled (Ctrl-C, SIGTERM): no image written"
        })
public final class RenderCommand implements Callable<Integer> {
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
            names = "--threads",
            paramLabel = "N",
            description = "render threads (default: the scene's, else all cores)")
    private Integer threads;

    @Option(
            names = "--allow-path",
            paramLabel = "DIR",
            description = "also let the scene read files (OBJ meshes) under DIR; by default only files in the scene"
                    + " file's folder tree are read (repeatable)")
    private List<Path> allowedPaths = new ArrayList<>();

    @Mixin
    private RenderOverrides overrides = new RenderOverrides();

    @Option(
            names = "--progress",
            paramLabel = "auto|bar|lines|none",
            defaultValue = "auto",
            description = "progress on stderr: a bar in a terminal, lines otherwise (default: ${DEFAULT-VALUE})")
    private ProgressMode progress;

    @Option(
            names = {"-q", "--quiet"},
            description = "print only errors (no progress, no statistics)")
    private boolean quiet;

    /** Where this command runs: its own JVM unless the render daemon hosts it for a client. */
    private RenderHost host = RenderHost.LOCAL;

    /** Runs this command for a client of the render daemon instead of in its own JVM. */
    void hostedBy(RenderHost daemonHost) {
        this.host = daemonHost;
    }

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (threads != null && (threads < 1 || threads > Limits.maxThreads())) {
            throw new BadInputException("--threads must be in " + Limits.threadRange() + ", but was " + threads);
        }
        overrides.check();

        SceneDocument document = SceneLoader.read(sceneFile);
        document = applyOverrides(document);
        for (Path folder : allowedPaths) {
            if (!Files.isDirectory(folder)) {
                throw new BadInputException("--allow-path " + Printable.of(folder.toString()) + ": not a folder");
            }
        }
        LoadedScene loaded = SceneLoader.build(document, sceneFile, allowedPaths);
        for (String warning : loaded.warnings()) err.println("warning: " + Printable.message(warning));

        Path target = output != null
                ? OutputFile.check(output, false)
                : OutputFile.check(OutputFile.defaultFor(loaded.scene().getName()), true);
        boolean existed = Files.exists(target);

        Camera camera = loaded.camera();
        String unchanged = existed ? "; " + Printable.message(target.toString()) + " was left unchanged" : "";
        // Ctrl-C or SIGTERM during the render cancels it (in the daemon: the client's); this thread reports it.
        RenderHost.CancelGuard guard = host.guard(camera);
        ProgressMode mode = quiet ? ProgressMode.NONE : progress;
        try (RenderProgress listener = RenderProgress.create(mode, host.terminal(), host.interactive(), err)) {
            camera.setProgressListener(listener);
            camera.renderImage();
            if (guard.signalled()) throw new CancellationException("cancelled by the user");
        } catch (CancellationException e) {
            err.println("render cancelled: no image written" + unchanged);
            err.flush();
            return ExitCodes.CANCELLED;
        } catch (RuntimeException | Error e) {
            err.println("render failed: no image written" + unchanged);
            throw e;
        } finally {
            guard.close();
        }
        try {
            camera.writeToImage(target);
        } catch (RuntimeException e) {
            err.println("writing failed: no image written" + unchanged);
            throw e;
        }
        if (!quiet) {
            out.println("wrote " + Printable.message(target.toString()));
            out.print(camera.getLastStatistics().format());
            if (camera.getLastProgressiveReport() != null) {
                out.println(camera.getLastProgressiveReport().describe());
            }
            out.flush();
        }
        return ExitCodes.OK;
    }

    /** The command-line options written into the document, so the loader validates them like the file. */
    private SceneDocument applyOverrides(SceneDocument d) {
        SceneDocument o = overrides.apply(d);
        RenderDocument r = o.render();
        return threads == null || r == null ? o : o.withRender(r.withThreads(threads));
    }
}
