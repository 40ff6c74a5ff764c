package cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The command line as a user runs it: exit codes, output files, messages, and no partial or stale images. */
class RaytracerCliTest {
    /** A tiny scene (8 x 4 pixels) that renders in milliseconds. */
    private static final String TINY = """
            {
              "camera": {"location": [0, -10, 0], "lookAt": [0, 0, 0], "vpDistance": 10, "vpWidth": 4,
                         "vpHeight": 2},
              "render": {"width": 8, "height": 4},
              "lights": [{"type": "directional", "color": [255, 255, 255], "direction": [0, 1, -1]}],
              "geometries": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"kD": 0.8}}]
            }
            """;

    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        return RaytracerCli.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
    }

    private Path tinyScene() throws IOException {
        return Files.writeString(dir.resolve("tiny.json"), TINY);
    }

    private static BufferedImage read(Path png) throws IOException {
        return ImageIO.read(png.toFile());
    }

    @Test
    void helpAndVersionExitZero() {
        assertEquals(0, run("--help"));
        assertTrue(out.toString().contains("render"), out.toString());
        assertEquals(0, run("render", "--help"));
        assertTrue(out.toString().contains("--bvh=on|off"), out.toString());
        assertEquals(0, run("--version"));
        assertTrue(out.toString().contains("raytracer "), out.toString());
    }

    @Test
    void usageErrorsExitTwo() {
        assertEquals(ExitCodes.BAD_INPUT, run());
        assertEquals(ExitCodes.BAD_INPUT, run("render"));
        assertEquals(ExitCodes.BAD_INPUT, run("render", "x.json", "--threads", "two"));
        assertEquals(ExitCodes.BAD_INPUT, run("render", "x.json", "--bvh", "maybe"));
        assertEquals(ExitCodes.BAD_INPUT, run("frobnicate"));
    }

    @Test
    void rendersTheSceneWithOverrides() throws IOException {
        Path scene = tinyScene();
        Path png = dir.resolve("out.png");
        assertEquals(0, run("render", scene.toString(), "-o", png.toString(), "--progress", "lines"), err.toString());
        BufferedImage image = read(png);
        assertEquals(8, image.getWidth());
        assertEquals(4, image.getHeight());
        assertTrue(out.toString().startsWith("wrote " + png.toAbsolutePath()), out.toString());
        assertTrue(err.toString().contains("render: 100% (1/1 tiles)"), err.toString());

        // --width alone keeps the aspect ratio; every override reaches the render.
        assertEquals(
                0,
                run(
                        "render",
                        scene.toString(),
                        "-o",
                        png.toString(),
                        "--width",
                        "40",
                        "--threads",
                        "1",
                        "--bvh",
                        "off",
                        "--samples",
                        "4",
                        "-q"));
        image = read(png);
        assertEquals(40, image.getWidth());
        assertEquals(20, image.getHeight());
        assertEquals(0, run("render", scene.toString(), "-o", png.toString(), "--width", "10", "--height", "10", "-q"));
        assertEquals(10, read(png).getHeight());
    }

    @Test
    void bvhOnAndOffGiveTheSameImage() throws IOException {
        Path scene = tinyScene();
        Path on = dir.resolve("on.png"), off = dir.resolve("off.png");
        assertEquals(0, run("render", scene.toString(), "-o", on.toString(), "--bvh", "on", "-q"));
        assertEquals(0, run("render", scene.toString(), "-o", off.toString(), "--bvh", "OFF", "-q"));
        BufferedImage a = read(on), b = read(off);
        assertArrayEquals(a.getRGB(0, 0, 8, 4, null, 0, 8), b.getRGB(0, 0, 8, 4, null, 0, 8));
        assertTrue(a.getRGB(4, 2) != a.getRGB(0, 0), "the sphere is visible against the background");
    }

    @Test
    void badSceneExitsTwoNamingFileAndPlaceAndWritesNothing() throws IOException {
        Path scene = Files.writeString(dir.resolve("bad.json"), TINY.replace("\"radius\": 1", "\"radius\": -1"));
        Path png = dir.resolve("out.png");
        assertEquals(ExitCodes.BAD_INPUT, run("render", scene.toString(), "-o", png.toString()));
        assertEquals(
                "error: " + scene + ":6:58: $.geometries[0].radius: sphere radius must be positive and finite, but"
                        + " was -1.0",
                err.toString().strip());
        assertFalse(Files.exists(png));
        assertEquals(
                ExitCodes.BAD_INPUT, run("render", dir.resolve("missing.json").toString()));
        assertTrue(err.toString().contains("missing.json: scene file not found"), err.toString());
    }

    @Test
    void badOptionValuesExitTwo() throws IOException {
        Path scene = tinyScene();
        Path png = dir.resolve("out.png");
        assertEquals(ExitCodes.BAD_INPUT, run("render", scene.toString(), "-o", png.toString(), "--threads", "0"));
        assertTrue(
                err.toString().contains("--threads must be in [1, " + primitives.Limits.maxThreads() + "] ("),
                err.toString());
        assertTrue(err.toString().contains("but was 0"), err.toString());
        assertEquals(ExitCodes.BAD_INPUT, run("render", scene.toString(), "-o", png.toString(), "--samples", "-3"));
        assertEquals(
                ExitCodes.BAD_INPUT,
                run("render", scene.toString(), "-o", dir.resolve("x.jpg").toString()));
        assertTrue(err.toString().contains("must be a .png file name"), err.toString());
        assertFalse(Files.exists(png));
    }

    @Test
    void outputInAMissingFolderExitsTwoAndCreatesNothing() throws IOException {
        Path scene = tinyScene();
        Path missing = dir.resolve("no-such-folder");
        assertEquals(
                ExitCodes.BAD_INPUT,
                run("render", scene.toString(), "-o", missing.resolve("a.png").toString()));
        assertTrue(err.toString().contains("folder " + missing + " does not exist"), err.toString());
        assertFalse(Files.exists(missing));
        Path file = Files.writeString(dir.resolve("a-file"), "x");
        assertEquals(
                ExitCodes.BAD_INPUT,
                run("render", scene.toString(), "-o", file.resolve("a.png").toString()));
        assertEquals(ExitCodes.BAD_INPUT, run("render", scene.toString(), "-o", dir.toString()));
    }

    @Test
    void outputInAnUnwritableFolderExitsTwo() throws IOException {
        Path scene = tinyScene();
        Assumptions.assumeTrue(Files.isDirectory(Path.of("/proc")), "Linux: /proc accepts no new files");
        assertEquals(ExitCodes.BAD_INPUT, run("render", scene.toString(), "-o", "/proc/out.png"));
        assertTrue(err.toString().contains("folder /proc is not writable"), err.toString());
    }

    @Test
    void outputInAReadOnlyFolderExitsTwo() throws IOException {
        Path scene = tinyScene();
        Path locked = Files.createDirectory(dir.resolve("locked"));
        Files.setPosixFilePermissions(locked, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            boolean rootIgnoresPermissions;
            try {
                Files.delete(Files.createTempFile(locked, "probe", ".tmp"));
                rootIgnoresPermissions = true;
            } catch (IOException expected) {
                rootIgnoresPermissions = false;
            }
            Assumptions.assumeFalse(rootIgnoresPermissions, "running as root: permission bits do not apply");
            assertEquals(
                    ExitCodes.BAD_INPUT,
                    run(
                            "render",
                            scene.toString(),
                            "-o",
                            locked.resolve("a.png").toString()));
            assertTrue(err.toString().contains("is not writable"), err.toString());
        } finally {
            Files.setPosixFilePermissions(locked, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    @Test
    void anOldImageIsLeftUntouchedWhenTheSceneIsBad() throws IOException {
        Path png = Files.write(dir.resolve("old.png"), new byte[] {1, 2, 3});
        FileTime before = FileTime.fromMillis(1_000_000_000_000L);
        Files.setLastModifiedTime(png, before);
        Path scene = Files.writeString(dir.resolve("bad.json"), "{\"camera\": ");
        assertEquals(ExitCodes.BAD_INPUT, run("render", scene.toString(), "-o", png.toString()));
        assertArrayEquals(new byte[] {1, 2, 3}, Files.readAllBytes(png));
        assertEquals(before, Files.getLastModifiedTime(png));
    }

    @Test
    void aRenderFailureExitsOneAndLeavesNoPartialImage() throws IOException {
        Path png = Files.write(dir.resolve("old.png"), new byte[] {1, 2, 3});
        // A 64 x 64 render has 16 tiles; the progress output fails at 50%, in a render thread, mid-render.
        Path scene = Files.writeString(
                dir.resolve("tiles.json"),
                TINY.replace("\"width\": 8, \"height\": 4", "\"width\": 64, \"height\": 64"));
        Writer failing = new Writer() {
            private boolean failed;

            @Override
            public void write(char[] buffer, int offset, int length) {
                String text = new String(buffer, offset, length);
                if (!failed && text.contains("50%")) {
                    failed = true;
                    throw new IllegalStateException("simulated failure during the render");
                }
                err.write(text);
            }

            @Override
            public void flush() {}

            @Override
            public void close() {}
        };
        int code = RaytracerCli.run(
                new String[] {"render", scene.toString(), "-o", png.toString(), "--progress", "lines", "--threads", "2"
                },
                new PrintWriter(out, true),
                new PrintWriter(failing, true));
        assertEquals(ExitCodes.RENDER_FAILED, code, err.toString());
        assertTrue(
                err.toString()
                        .contains("render failed: no image written; " + png.toAbsolutePath() + " was left unchanged"),
                err.toString());
        assertArrayEquals(new byte[] {1, 2, 3}, Files.readAllBytes(png));
        try (Stream<Path> files = Files.list(dir)) {
            List<String> names = new ArrayList<>(
                    files.map(p -> p.getFileName().toString()).sorted().toList());
            assertEquals(List.of("old.png", "tiles.json"), names, "no temporary or partial files are left");
        }
    }

    static List<String> shippedScenes() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            return files.map(Path::toString)
                    .filter(f -> f.endsWith(".json"))
                    .sorted()
                    .toList();
        }
    }

    @ParameterizedTest
    @MethodSource("shippedScenes")
    void everyShippedSceneRenders(String scene) throws IOException {
        Path png = dir.resolve("thumbnail.png");
        // README's main job renders showcase.json at full size; a thumbnail proves each file and the command work.
        assertEquals(
                0, run("render", scene, "-o", png.toString(), "--width", "32", "--samples", "1", "-q"), err.toString());
        assertEquals(32, read(png).getWidth());
        assertEquals("", out.toString(), "quiet");
    }
}
