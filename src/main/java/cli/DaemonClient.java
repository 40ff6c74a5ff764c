package cli;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import launch.JavaLaunch;

/**
 * {@code raytracer --daemon render ...}: runs the render command in the render daemon ({@link RenderDaemon}),
 * starting one when none serves this program in this folder (with the Vector API module whenever the JDK has it,
 * so the client itself needs no {@code --add-modules}), and relays its output and exit code.
 * {@code raytracer --daemon stop} stops it. The client loads neither the renderer nor Jackson (of picocli, only the
 * few classes the verifier needs for {@link RaytracerCli}); Ctrl-C cancels the render in the daemon and waits for its
 * report.
 */
final class DaemonClient {
    /** The option, first on the command line, that sends the command to the daemon. */
    static final String OPTION = "--daemon";
    /** How long a client waits for a daemon it started to listen. */
    static final Duration START_TIMEOUT = Duration.ofSeconds(30);

    private final DaemonAddress address;
    private final JavaLaunch launch;
    private final OutputStream out;
    private final OutputStream err;

    DaemonClient(DaemonAddress address, JavaLaunch launch, OutputStream out, OutputStream err) {
        this.address = address;
        this.launch = launch;
        this.out = out;
        this.err = err;
    }

    /**
     * Runs the arguments after {@code --daemon} from this process' command line: {@code render ...} or
     * {@code stop}.
     *
     * @param args the arguments after {@code --daemon}
     * @return the exit code
     */
    static int main(List<String> args) {
        try {
            JavaLaunch launch = JavaLaunch.ofThisProgram();
            DaemonAddress address = DaemonAddress.of(launch, workingFolder());
            return new DaemonClient(address, launch, System.out, System.err).run(args);
        } catch (BadInputException e) {
            System.err.println("error: " + e.getMessage());
            return ExitCodes.BAD_INPUT;
        } catch (IOException e) {
            System.err.println("error: --daemon: " + e);
            return ExitCodes.RENDER_FAILED;
        }
    }

    /**
     * Runs {@code render ...} in the daemon (started if need be), or {@code stop}s it.
     *
     * @param args the arguments after {@code --daemon}
     * @return the exit code of the command, as the command line in a JVM of its own would give it
     * @throws IOException if the daemon cannot be reached or started
     */
    int run(List<String> args) throws IOException {
        if (args.equals(List.of("stop"))) return stop();
        if (args.isEmpty() || !args.get(0).equals("render")) {
            say(
                    err,
                    "error: " + OPTION + " runs the render command (" + OPTION + " render scene.json ...), or " + OPTION
                            + " stop to stop the daemon, but was given "
                            + (args.isEmpty() ? "nothing" : String.join(" ", args)));
            return ExitCodes.BAD_INPUT;
        }
        var request = new DaemonProtocol.Request(
                DaemonProtocol.Kind.RENDER, workingFolder().toString(), Terminal.interactive(), args);
        try {
            return send(request);
        } catch (NotTaken ended) {
            // The daemon ended (idle, stopped, rebuilt) as the request came, before taking it: start another.
            return send(request);
        }
    }

    /** Sends the request to a live daemon, or to one started for it, and relays its answer. */
    private int send(DaemonProtocol.Request request) throws IOException {
        SocketChannel live = connect();
        try (SocketChannel channel = live != null ? live : start()) {
            try {
                request.send(channel);
            } catch (IOException e) {
                throw new NotTaken(e);
            }
            return relay(channel);
        }
    }

    /** The connection ended before the daemon took the request, so it can be sent again. */
    private static final class NotTaken extends IOException {
        NotTaken(IOException cause) {
            super("the render daemon ended before it took the request: " + cause.getMessage(), cause);
        }
    }

    private int stop() throws IOException {
        SocketChannel channel = connect();
        if (channel == null) {
            say(out, "no render daemon serves this program in this folder");
            return ExitCodes.OK;
        }
        try (channel) {
            new DaemonProtocol.Request(DaemonProtocol.Kind.STOP, workingFolder().toString(), false, List.of())
                    .send(channel);
            int code = relay(channel);
            say(out, "stopped the render daemon");
            return code;
        } catch (NotTaken ended) {
            say(out, "no render daemon serves this program in this folder (one was ending)");
            return ExitCodes.OK;
        }
    }

    /** Copies the daemon's frames to stdout and stderr until its exit code; Ctrl-C meanwhile cancels the render. */
    private int relay(SocketChannel channel) throws IOException {
        CountDownLatch answered = new CountDownLatch(1);
        AtomicBoolean running = new AtomicBoolean();
        Thread cancel = new Thread(() -> cancelAndWait(channel, running, answered), "cancel-daemon-render");
        Runtime.getRuntime().addShutdownHook(cancel);
        try {
            while (true) {
                DaemonProtocol.Frame frame = DaemonProtocol.readFrame(channel);
                if (frame.kind() == DaemonProtocol.EXIT) {
                    answered.countDown();
                    return frame.body().getInt();
                }
                if (frame.kind() == DaemonProtocol.RUNNING) {
                    running.set(true);
                    continue;
                }
                OutputStream target = frame.kind() == DaemonProtocol.OUT ? out : err;
                target.write(frame.body().array(), 0, frame.body().limit());
                target.flush();
            }
        } catch (IOException e) {
            if (!running.get()) throw new NotTaken(e);
            say(
                    err,
                    "render failed: the render daemon ended without an answer (" + e.getMessage() + "); its log: "
                            + address.log());
            return ExitCodes.RENDER_FAILED;
        } finally {
            answered.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(cancel);
            } catch (IllegalStateException shuttingDown) {
                // the hook is running: it returns once the answer came
            }
        }
    }

    /**
     * In a shutdown (Ctrl-C): asks the daemon to cancel, and holds the exit until its report has been relayed. A
     * request still waiting for its turn is not waited for: the daemon finds the connection closed when it takes it,
     * and cancels at once.
     */
    private static void cancelAndWait(SocketChannel channel, AtomicBoolean running, CountDownLatch answered) {
        try {
            DaemonProtocol.writeFully(channel, ByteBuffer.wrap(new byte[] {DaemonProtocol.CANCEL}));
            if (running.get()) answered.await(CancelOnShutdown.GRACE_MILLIS, TimeUnit.MILLISECONDS);
        } catch (IOException | InterruptedException gone) {
            // the daemon is gone or the wait was cut short: nothing more to relay
        }
    }

    /** A connection to a live daemon at the address, or null if none listens there. */
    private SocketChannel connect() {
        if (!Files.exists(address.socket())) return null;
        try {
            return SocketChannel.open(UnixDomainSocketAddress.of(address.socket()));
        } catch (IOException noneListens) {
            return null;
        }
    }

    /** Starts a daemon and connects to it; a daemon started by another client at the same moment serves as well. */
    private SocketChannel start() throws IOException {
        List<String> args = List.of(address.socket().toString());
        Process daemon = new ProcessBuilder(launch.withVectorApi().command(RenderDaemon.class.getName(), args))
                .directory(workingFolder().toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .redirectErrorStream(true)
                .redirectOutput(address.log().toFile())
                .start();
        long deadline = System.nanoTime() + START_TIMEOUT.toNanos();
        while (System.nanoTime() < deadline) {
            SocketChannel channel = connect();
            if (channel != null) {
                if (daemon.isAlive()) {
                    say(
                            err,
                            "started a render daemon (process " + daemon.pid() + "; it exits after "
                                    + RenderDaemon.IDLE.toMinutes() + " idle minutes, or on " + OPTION + " stop)");
                }
                return channel;
            }
            if (!daemon.isAlive() && daemon.exitValue() != 0) {
                throw new IOException(
                        "the render daemon did not start (exit " + daemon.exitValue() + "); its log: " + address.log());
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while the render daemon started", e);
            }
        }
        daemon.destroy();
        throw new IOException("the render daemon did not listen within " + START_TIMEOUT.toSeconds() + " s; its log: "
                + address.log());
    }

    private static Path workingFolder() {
        return Path.of("").toAbsolutePath().normalize();
    }

    private static void say(OutputStream stream, String line) throws IOException {
        stream.write((line + System.lineSeparator()).getBytes(StandardCharsets.UTF_8));
        stream.flush();
    }
}
