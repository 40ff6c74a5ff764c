package cli;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import launch.JavaLaunch;
import picocli.CommandLine;
import primitives.Printable;
import renderer.Camera;

/**
 * The render daemon: a JVM that stays running between {@code raytracer --daemon render ...} commands, so that
 * every render after its first runs in code the JIT has already compiled (a fresh JVM spends most of a short
 * render compiling it; docs/CLI.md gives the figures). It serves one command at a time, from clients of the same
 * user in the same working folder ({@link DaemonAddress}), runs exactly what the command line would run, with the
 * same checks, output and exit codes, and exits after {@link #IDLE} without a command, on {@code --daemon stop}, or
 * when the program is rebuilt.
 *
 * <p>The client's Ctrl-C, or its end, cancels the render as Ctrl-C cancels it in a JVM of its own. The daemon
 * ignores SIGINT and SIGHUP, which the terminal sends to the client's whole process group, and ends on SIGTERM.
 * An {@link Error} in a command (such as running out of memory) is reported to its client, and then the daemon
 * ends, as its state can no longer be trusted.
 */
public final class RenderDaemon {
    /** How long a daemon waits for a command before it exits. */
    static final Duration IDLE = Duration.ofMinutes(10);
    /** How often an idle daemon checks whether the program was rebuilt. */
    private static final long REBUILD_CHECK_MILLIS = 30_000;

    private final Path workingFolder = Path.of("").toAbsolutePath().normalize();

    private RenderDaemon() {}

    /**
     * Serves the socket given as the argument until idle or stopped. Started by {@link DaemonClient}, with its output
     * in the daemon's log.
     *
     * @param args the socket path
     * @throws IOException if the socket cannot be served
     */
    public static void main(String[] args) throws IOException {
        ignore("INT");
        ignore("HUP");
        serve(DaemonAddress.at(Path.of(args[0])), IDLE);
    }

    @SuppressWarnings("restriction")
    private static void ignore(String signal) {
        try {
            sun.misc.Signal.handle(new sun.misc.Signal(signal), sun.misc.SignalHandler.SIG_IGN);
        } catch (IllegalArgumentException notOnThisSystem) {
            // no such signal here: nothing to ignore
        }
    }

    /**
     * Serves {@code address} until no command came for {@code idle}, a client asked to stop, or a command ended in
     * an {@link Error}; returns at once if another daemon already serves it.
     *
     * @param address the socket, and the lock held while serving
     * @param idle how long to wait for a command
     * @return whether this daemon served (false: another one holds the lock)
     * @throws IOException if the socket cannot be bound
     */
    static boolean serve(DaemonAddress address, Duration idle) throws IOException {
        String classPath = JavaLaunch.ofThisProgram().classPath();
        return serve(address, idle, () -> DaemonAddress.newestFile(classPath), REBUILD_CHECK_MILLIS);
    }

    /**
     * As {@link #serve(DaemonAddress, Duration)}, with the program's build stamp read from {@code build} every
     * {@code checkMillis} while idle: when it changes, the daemon ends.
     */
    static boolean serve(DaemonAddress address, Duration idle, LongSupplier build, long checkMillis)
            throws IOException {
        try (FileChannel lockFile =
                        FileChannel.open(address.lock(), StandardOpenOption.CREATE, StandardOpenOption.WRITE);
                FileLock lock = tryLock(lockFile)) {
            if (lock == null) {
                System.out.println("another daemon serves " + address.socket());
                return false;
            }
            Files.deleteIfExists(address.socket()); // left by a daemon that was killed
            try (ServerSocketChannel server = ServerSocketChannel.open(StandardProtocolFamily.UNIX);
                    Selector selector = Selector.open()) {
                server.bind(UnixDomainSocketAddress.of(address.socket()));
                server.configureBlocking(false);
                server.register(selector, SelectionKey.OP_ACCEPT);
                RenderDaemon daemon = new RenderDaemon();
                System.out.println("raytracer daemon " + ProcessHandle.current().pid() + " serves " + address.socket()
                        + " in " + daemon.workingFolder);
                daemon.loop(server, selector, idle, build, checkMillis);
            } finally {
                Files.deleteIfExists(address.socket());
            }
            return true;
        }
    }

    /** The lock, or null when another daemon holds it (in another process, or in this one). */
    private static FileLock tryLock(FileChannel lockFile) throws IOException {
        try {
            return lockFile.tryLock();
        } catch (OverlappingFileLockException heldInThisJvm) {
            return null;
        }
    }

    /**
     * Accepts commands until idle, stopped or rebuilt: a rebuild of the program (a newer file on its class path)
     * gives clients a new address, so a daemon running the old code would only wait out its idle time.
     */
    private void loop(
            ServerSocketChannel server, Selector selector, Duration idle, LongSupplier build, long checkMillis)
            throws IOException {
        long built = build.getAsLong();
        long idleSince = System.nanoTime();
        while (!Thread.currentThread().isInterrupted()) {
            long idleLeft = idle.toNanos() - (System.nanoTime() - idleSince);
            if (idleLeft <= 0) {
                System.out.println("idle for " + idle + ": exiting");
                return;
            }
            if (selector.select(Math.max(1, Math.min(TimeUnit.NANOSECONDS.toMillis(idleLeft), checkMillis))) == 0) {
                if (build.getAsLong() != built) {
                    System.out.println("the program was rebuilt: exiting");
                    return;
                }
                continue;
            }
            selector.selectedKeys().clear();
            SocketChannel client = server.accept();
            if (client == null) continue;
            try (client) {
                client.configureBlocking(true);
                if (!handle(client)) return;
            }
            idleSince = System.nanoTime();
        }
        System.out.println("interrupted: exiting");
    }

    /** Runs one client's request; false when the daemon must end (stop asked, or an Error). */
    private boolean handle(SocketChannel client) {
        DaemonProtocol.Request request;
        try {
            request = DaemonProtocol.Request.receive(client);
        } catch (IOException e) {
            System.out.println("a connection that sent no request: " + e.getMessage());
            return true;
        }
        try {
            DaemonProtocol.running(client);
        } catch (IOException gone) {
            System.out.println("a client that left before its turn");
            return true;
        }
        if (request.kind() == DaemonProtocol.Kind.STOP) {
            reply(client, ExitCodes.OK);
            System.out.println("stopped by a client");
            return false;
        }
        PrintWriter out = writer(client, DaemonProtocol.OUT);
        PrintWriter err = writer(client, DaemonProtocol.ERR);
        Session session = new Session(client, request.interactive());
        long start = System.nanoTime();
        int code;
        boolean fatal = false;
        try {
            code = run(request, out, err, session);
        } catch (Throwable t) { // an Error escaped the command's own handler: report it, then end
            err.println("render failed: " + Printable.message(t.toString()) + "; the render daemon ends");
            code = ExitCodes.RENDER_FAILED;
            fatal = true;
        } finally {
            session.finish();
        }
        out.flush();
        err.flush();
        session.terminal().flush();
        reply(client, code);
        System.out.printf(
                Locale.ROOT,
                "%s -> exit %d in %.3f s%n",
                Printable.message(String.join(" ", request.args())),
                code,
                (System.nanoTime() - start) * 1e-9);
        return !fatal;
    }

    private int run(DaemonProtocol.Request request, PrintWriter out, PrintWriter err, Session session) {
        List<String> args = request.args();
        if (!request.workingFolder().equals(workingFolder.toString())) {
            err.println("error: this render daemon serves " + Printable.message(workingFolder.toString()) + ", not "
                    + Printable.message(request.workingFolder()));
            return ExitCodes.BAD_INPUT;
        }
        if (args.isEmpty() || !args.get(0).equals("render")) {
            err.println("error: the render daemon runs only the render command, but was asked "
                    + Printable.message(String.join(" ", args)));
            return ExitCodes.BAD_INPUT;
        }
        CommandLine commandLine = RaytracerCli.commandLine(out, err);
        RenderCommand render = commandLine.getSubcommands().get("render").getCommand();
        render.hostedBy(session);
        return commandLine.execute(args.toArray(String[]::new));
    }

    private static PrintWriter writer(SocketChannel client, byte kind) {
        return new PrintWriter(
                new OutputStreamWriter(DaemonProtocol.frames(client, kind), StandardCharsets.UTF_8), true);
    }

    private static void reply(SocketChannel client, int code) {
        try {
            DaemonProtocol.exit(client, code);
        } catch (IOException gone) {
            // the client has gone (Ctrl-C): nobody to tell
        }
    }

    /**
     * One client's command: its terminal for a progress bar, and a thread that waits for its cancel (one byte, or
     * the connection's end) and then cancels the render until the command has finished.
     */
    private static final class Session implements RenderHost {
        private final SocketChannel client;
        private final boolean interactive;
        private final PrintStream terminal;
        private final CountDownLatch finished = new CountDownLatch(1);
        private volatile boolean cancelRequested;
        private volatile Camera camera;

        Session(SocketChannel client, boolean interactive) {
            this.client = client;
            this.interactive = interactive;
            this.terminal =
                    new PrintStream(DaemonProtocol.frames(client, DaemonProtocol.ERR), true, StandardCharsets.UTF_8);
            Thread watcher = new Thread(this::awaitCancel, "daemon-cancel");
            watcher.setDaemon(true);
            watcher.start();
        }

        private void awaitCancel() {
            try {
                DaemonProtocol.readFully(client, 1); // CANCEL; nothing else is ever sent
            } catch (IOException endOrClosed) {
                // the client ended, or this command finished and its connection was closed
            }
            if (finished.getCount() == 0) return;
            cancelRequested = true;
            CancelOnShutdown.cancelUntil(() -> camera, finished, Long.MAX_VALUE); // until the command ends
        }

        void finish() {
            finished.countDown();
        }

        @Override
        public PrintStream terminal() {
            return terminal;
        }

        @Override
        public boolean interactive() {
            return interactive;
        }

        @Override
        public CancelGuard guard(Camera rendering) {
            camera = rendering;
            return new CancelGuard() {
                @Override
                public boolean signalled() {
                    return cancelRequested;
                }

                @Override
                public void close() {
                    camera = null;
                }
            };
        }
    }
}
