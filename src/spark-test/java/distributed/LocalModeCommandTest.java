package distributed;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cli.RaytracerCli;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The local-mode command as a user runs it: a new JVM with the Java 17 flags and the Spark properties of
 * {@code exec:exec@spark} (local[2,4], loopback, no UI), here with the first attempt of a tile or frame forced to
 * fail. Its PNG files are the pixels the {@code raytracer render} CLI writes for the same scene.
 */
class LocalModeCommandTest {
    @TempDir
    Path dir;

    /** Runs {@code SparkRenderMain} in a new JVM and returns its exit code; its output goes to files in dir. */
    private int runLocalMode(String failFirstAttempt, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // This JVM's flags: surefire's argLine holds the --add-opens list that the exec:exec@spark command uses.
        command.addAll(ManagementFactory.getRuntimeMXBean().getInputArguments());
        command.addAll(List.of(
                "-Dspark.master=local[2,4]",
                "-Dspark.driver.host=127.0.0.1",
                "-Dspark.driver.bindAddress=127.0.0.1",
                "-Dspark.ui.enabled=false",
                "-D" + FaultInjection.PROPERTY + "=" + failFirstAttempt,
                "-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                SparkRenderMain.class.getName()));
        command.addAll(List.of(args));
        Process process = new ProcessBuilder(command)
                .redirectOutput(dir.resolve("stdout.txt").toFile())
                .redirectError(dir.resolve("stderr.txt").toFile())
                .start();
        if (!process.waitFor(5, TimeUnit.MINUTES)) {
            process.destroyForcibly();
            throw new AssertionError("the local-mode command did not finish in 5 minutes");
        }
        return process.exitValue();
    }

    private String output() throws IOException {
        return Files.readString(dir.resolve("stdout.txt")) + Files.readString(dir.resolve("stderr.txt"));
    }

    private static int[] pixels(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private static Path renderWithCli(Path scene, Path png) {
        StringWriter err = new StringWriter();
        int code = RaytracerCli.run(
                new String[] {"render", scene.toString(), "-q", "-o", png.toString()},
                new PrintWriter(new StringWriter(), true),
                new PrintWriter(err, true));
        assertEquals(0, code, err.toString());
        return png;
    }

    @Test
    void tilesWriteTheImageTheCliWrites() throws Exception {
        Path scene = TestScenes.softShadows(dir, 64, 40);
        Path out = dir.resolve("tiles.png");
        int code = runLocalMode("2", "tiles", scene.toString(), "--tiles", "2x2", "-o", out.toString());
        assertEquals(0, code, output());
        assertTrue(output().contains("wrote " + out), output());
        assertTrue(output().contains("spark: 4 tiles (2x2) rendered in"), output());
        assertTrue(output().contains("(2 cores), 1 failed task attempts retried"), output());
        assertArrayEquals(pixels(renderWithCli(scene, dir.resolve("cli.png"))), pixels(out));
    }

    @Test
    void framesAreWrittenAsNumberedFiles() throws Exception {
        Path scene = TestScenes.softShadows(dir, 32, 20);
        Path path = Files.writeString(
                dir.resolve("path.json"),
                "{\"keyframes\": [{\"frame\": 0, \"location\": [0, -300, 170], \"target\": [0, 0, 20]},"
                        + " {\"frame\": 2, \"location\": [300, 0, 170], \"target\": [0, 0, 20]}]}");
        Path frames = Files.createDirectories(dir.resolve("frames"));
        int code = runLocalMode(
                "0",
                "frames",
                scene.toString(),
                "--path",
                path.toString(),
                "-o",
                frames + File.separator + "orbit-%03d.png");
        assertEquals(0, code, output());
        assertTrue(output().contains("wrote 3 frames: "), output());
        assertTrue(output().contains("(2 cores), 1 failed task attempts retried"), output());
        try (var files = Files.list(frames)) {
            assertEquals(
                    List.of("orbit-000.png", "orbit-001.png", "orbit-002.png"),
                    files.map(f -> f.getFileName().toString()).sorted().toList());
        }
        // Frame 0 is the scene's own camera: the CLI renders the same image.
        assertArrayEquals(
                pixels(renderWithCli(scene, dir.resolve("cli.png"))), pixels(frames.resolve("orbit-000.png")));
    }
}
