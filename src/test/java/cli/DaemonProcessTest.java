package cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code raytracer --daemon ...} as a user runs it, in processes of their own: the first command starts the daemon,
 * the next one reuses it and writes the same image, the client loads neither the renderer nor Jackson, SIGTERM to
 * the client (what Ctrl-C does too) cancels the render in the daemon with the usual report, and {@code --daemon
 * stop} ends it. Each test has its own {@code java.io.tmpdir}, so its daemon is its own.
 */
class DaemonProcessTest {
    private static final Pattern STARTED = Pattern.compile("started a render daemon \\(process ([0-9]+)");

    @TempDir
    Path tmp;

    private final List<Long> daemons = new ArrayList<>();

    @AfterEach
    void stopDaemons() throws Exception {
        run("--daemon", "stop");
        for (long pid : daemons) ProcessHandle.of(pid).ifPresent(ProcessHandle::destroy);
    }

    @Test
    void theFirstCommandStartsTheDaemonAndTheNextReusesIt() throws Exception {
        Path first = tmp.resolve("first.png");
        Path second = tmp.resolve("second.png");
        Result one = run(render(first));
        assertEquals(ExitCodes.OK, one.code, one.output);
        Matcher started = STARTED.matcher(one.output);
        assertTrue(started.find(), one.output);
        daemons.add(Long.parseLong(started.group(1)));

        Result two = run(render(second));
        assertEquals(ExitCodes.OK, two.code, two.output);
        assertFalse(two.output.contains("started a render daemon"), two.output);
        assertTrue(two.output.contains("wrote " + second), two.output);
        assertArrayEquals(Files.readAllBytes(first), Files.readAllBytes(second));

        Result stop = run("--daemon", "stop");
        assertEquals(ExitCodes.OK, stop.code, stop.output);
        assertTrue(stop.output.contains("stopped the render daemon"), stop.output);
        ProcessHandle daemon = ProcessHandle.of(daemons.get(0)).orElse(null);
        if (daemon != null) daemon.onExit().get(30, TimeUnit.SECONDS);
    }

    @Test
    void theClientLoadsNeitherTheRendererNorJackson() throws Exception {
        Result started = run(render(tmp.resolve("warm.png")));
        assertEquals(ExitCodes.OK, started.code, started.output);
        Matcher pid = STARTED.matcher(started.output);
        if (pid.find()) daemons.add(Long.parseLong(pid.group(1)));
        Result logged =
                run(List.of("-Xlog:class+load:file=" + tmp.resolve("classes.log")), render(tmp.resolve("x.png")));
        assertEquals(ExitCodes.OK, logged.code, logged.output);
        String classes = Files.readString(tmp.resolve("classes.log"));
        assertTrue(classes.contains("cli.DaemonClient"), "the log is the client's");
        // (The verifier loads a few picocli classes with RaytracerCli, about 2 ms; none of the render's.)
        for (String heavy : List.of(" renderer.", " scene.", " sceneio.", " com.fasterxml.jackson.")) {
            assertFalse(classes.contains(heavy), heavy + " was loaded by the client");
        }
    }

    @Test
    void sigtermToTheClientCancelsTheRenderInTheDaemon() throws Exception {
        Path image = tmp.resolve("street.png");
        CommandLineProcess.Ended client = CommandLineProcess.sigtermDuringStreetRender(
                List.of("-Djava.io.tmpdir=" + tmp), List.of("--daemon"), image.toString());
        String output = client.output();
        Matcher started = STARTED.matcher(output);
        if (started.find()) daemons.add(Long.parseLong(started.group(1)));
        assertEquals(143, client.exitValue(), output);
        assertTrue(output.contains("render cancelled: no image written"), output);
        assertFalse(Files.exists(image));
        Result after = run(render(tmp.resolve("after.png")));
        assertEquals(ExitCodes.OK, after.code, "the daemon serves on: " + after.output);
    }

    private static String[] render(Path image) {
        return new String[] {
            "--daemon", "render", "scenes/aa-edges.json", "-o", image.toString(), "--width", "64", "--height", "40"
        };
    }

    private record Result(int code, String output) {}

    private Result run(String... args) throws Exception {
        return run(List.of(), args);
    }

    private Result run(List<String> jvmOptions, String... args) throws Exception {
        List<String> options = new ArrayList<>(jvmOptions);
        options.add("-Djava.io.tmpdir=" + tmp);
        Process p = CommandLineProcess.builder(options, args)
                .redirectErrorStream(true)
                .start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the command ended");
        return new Result(p.exitValue(), output);
    }
}
