package cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import launch.JavaLaunch;

/** The command line in a JVM of its own, for tests that need a fresh JVM or a real process (signals, class loading). */
final class CommandLineProcess {
    private CommandLineProcess() {}

    /**
     * A process builder for {@code java JVM_OPTIONS -cp TEST_CLASSPATH cli.RaytracerCli ARGS}, with the JVM running
     * the tests and their class path.
     *
     * @param jvmOptions options for the child JVM, before its class path
     * @param args the command line's arguments
     * @return the builder, not started
     */
    static ProcessBuilder builder(List<String> jvmOptions, String... args) {
        JavaLaunch tests = launch();
        return new ProcessBuilder(
                new JavaLaunch(tests.java(), jvmOptions, tests.classPath()).command("cli.RaytracerCli", List.of(args)));
    }

    /**
     * The JVM running the tests, without options, on their class path (surefire's, where it runs them).
     *
     * @return the launch of a JVM like this one
     */
    static JavaLaunch launch() {
        return new JavaLaunch(
                ProcessHandle.current().info().command().orElse("java"),
                List.of(),
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")));
    }

    /**
     * Renders the street on one thread with progress lines in a process of its own, sends it SIGTERM once the render
     * has started (its first progress line), and returns the process, ended, with all it printed.
     *
     * @param jvmOptions options for the child JVM
     * @param commandLine the arguments before {@code render}: none, or {@code --daemon}
     * @param image the output image
     * @return the ended process and its output (stdout and stderr)
     */
    static Ended sigtermDuringStreetRender(List<String> jvmOptions, List<String> commandLine, String image)
            throws IOException, InterruptedException {
        List<String> args = new ArrayList<>(commandLine);
        args.addAll(List.of("render", "scenes/street.json", "-o", image, "--threads", "1", "--progress", "lines"));
        Process process = builder(jvmOptions, args.toArray(String[]::new))
                .redirectErrorStream(true)
                .start();
        StringBuilder output = new StringBuilder();
        var reader = process.inputReader(StandardCharsets.UTF_8);
        for (String line = reader.readLine(); line != null; line = reader.readLine()) {
            output.append(line).append('\n');
            if (line.startsWith("render:")) break;
        }
        process.toHandle().destroy(); // SIGTERM (Process.destroy would also close our end of its output)
        for (String line = reader.readLine(); line != null; line = reader.readLine())
            output.append(line).append('\n');
        if (!process.waitFor(30, TimeUnit.SECONDS)) throw new AssertionError("the process did not end: " + output);
        return new Ended(process.exitValue(), output.toString());
    }

    /** A process that has ended: its exit value and its output. */
    record Ended(int exitValue, String output) {}
}
