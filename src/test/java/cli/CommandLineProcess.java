package cli;

import java.util.ArrayList;
import java.util.List;

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
        List<String> command = new ArrayList<>();
        command.add(ProcessHandle.current().info().command().orElse("java"));
        command.addAll(jvmOptions);
        command.add("-cp");
        command.add(System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")));
        command.add("cli.RaytracerCli");
        command.addAll(List.of(args));
        return new ProcessBuilder(command);
    }
}
