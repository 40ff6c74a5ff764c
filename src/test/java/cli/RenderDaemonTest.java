package cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import launch.JavaLaunch;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The render daemon, served from a thread of this JVM: a render through it writes the same image, output and exit
 * code as the command line in its own JVM; bad input is reported the same way; a cancel, or a client that goes
 * away, stops the render without an image and leaves the daemon serving; stop and idleness end it, and a second
 * daemon never serves the same socket.
 */
class RenderDaemonTest {
    @TempDir
    Path folder;

    private DaemonAddress address;
    private final ExecutorService executor = Executors.newCachedThreadPool();
    private Future<Boolean> daemon;

    @BeforeEach
    void startDaemon() throws Exception {
        address = DaemonAddress.at(folder.resolve("test.sock"));
        daemon = executor.submit(() -> RenderDaemon.serve(address, Duration.ofMinutes(1)));
        awaitListening(address);
    }

    @AfterEach
    void stopDaemon() throws Exception {
        if (!daemon.isDone())
            client(new ByteArrayOutputStream(), new ByteArrayOutputStream()).run(List.of("stop"));
        daemon.get(30, TimeUnit.SECONDS);
    }

    @AfterEach
    void stopThreads() {
        executor.shutdownNow();
    }

    @Test
    void rendersTheSameImageAndOutputAsTheCommandLine() throws Exception {
        Path local = folder.resolve("local.png");
        Path remote = folder.resolve("daemon.png");
        StringWriter localOut = new StringWriter();
        int localCode = RaytracerCli.run(
                renderArgs("scenes/aa-edges.json", local).toArray(String[]::new),
                new PrintWriter(localOut),
                new PrintWriter(new StringWriter()));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = client(out, err).run(renderArgs("scenes/aa-edges.json", remote));
        assertEquals(ExitCodes.OK, localCode);
        assertEquals(ExitCodes.OK, code, err.toString(StandardCharsets.UTF_8));
        assertArrayEquals(Files.readAllBytes(local), Files.readAllBytes(remote), "the same PNG, byte for byte");
        assertEquals(withoutTimes(localOut.toString()).replace("local.png", "daemon.png"), withoutTimes(text(out)));
    }

    @Test
    void badInputIsReportedAsByTheCommandLine() throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = client(new ByteArrayOutputStream(), err)
                .run(List.of("render", folder.resolve("missing.json").toString()));
        assertEquals(ExitCodes.BAD_INPUT, code);
        assertTrue(text(err).startsWith("error: ") && text(err).contains("missing.json"), text(err));
    }

    @Test
    void onlyTheRenderCommandIsSent() throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assertEquals(
                ExitCodes.BAD_INPUT, client(new ByteArrayOutputStream(), err).run(List.of("report")));
        assertTrue(text(err).contains("runs the render command"), text(err));
        // A request that bypasses the client is refused by the daemon itself.
        Answer answer = ask(List.of("robustness"), Path.of("").toAbsolutePath().toString(), null);
        assertEquals(ExitCodes.BAD_INPUT, answer.code);
        assertTrue(answer.err.contains("runs only the render command"), answer.err);
    }

    @Test
    void aRequestFromAnotherFolderIsRefused() throws Exception {
        Answer answer = ask(renderArgs("scenes/aa-edges.json", folder.resolve("x.png")), "/elsewhere", null);
        assertEquals(ExitCodes.BAD_INPUT, answer.code);
        assertTrue(answer.err.contains("serves") && answer.err.contains("/elsewhere"), answer.err);
        assertFalse(Files.exists(folder.resolve("x.png")));
    }

    @Test
    void cancelStopsTheRenderWithoutAnImageAndTheDaemonServesOn() throws Exception {
        Path image = folder.resolve("street.png");
        Answer answer = ask(slowRender(image), Path.of("").toAbsolutePath().toString(), DaemonProtocol.CANCEL);
        assertEquals(ExitCodes.CANCELLED, answer.code, answer.err);
        assertTrue(answer.err.contains("render cancelled: no image written"), answer.err);
        assertFalse(Files.exists(image));
        assertEquals(List.of("test.lock", "test.sock"), list(folder), "no image and no temporary file");
        renderStillWorks();
    }

    @Test
    void aClientThatGoesAwayCancelsItsRender() throws Exception {
        Path image = folder.resolve("street.png");
        try (SocketChannel channel = SocketChannel.open(UnixDomainSocketAddress.of(address.socket()))) {
            request(slowRender(image), Path.of("").toAbsolutePath().toString()).send(channel);
            awaitProgress(channel, new StringBuilder());
        } // closed mid-render
        renderStillWorks(); // served after the cancelled render ended
        assertFalse(Files.exists(image));
    }

    @Test
    void aClientThatLeavesBeforeItsTurnRendersNothing() throws Exception {
        String here = Path.of("").toAbsolutePath().toString();
        Path second = folder.resolve("second.png");
        try (SocketChannel busy = SocketChannel.open(UnixDomainSocketAddress.of(address.socket()))) {
            request(slowRender(folder.resolve("street.png")), here).send(busy);
            awaitProgress(busy, new StringBuilder());
            try (SocketChannel waiting = SocketChannel.open(UnixDomainSocketAddress.of(address.socket()))) {
                request(slowRender(second), here).send(waiting);
            } // gone before the daemon took it
            DaemonProtocol.writeFully(busy, ByteBuffer.wrap(new byte[] {DaemonProtocol.CANCEL}));
            while (DaemonProtocol.readFrame(busy).kind() != DaemonProtocol.EXIT) {
                // the first render's report
            }
        }
        renderStillWorks(); // served after the second request was skipped or cancelled
        assertFalse(Files.exists(second));
    }

    @Test
    void aDaemonThatEndsAsTheRequestComesIsReplaced() throws Exception {
        stopDaemon(); // this test's address gets a listener that ends as the request comes
        DaemonAddress ending = DaemonAddress.at(folder.resolve("ending.sock"));
        try (ServerSocketChannel listener = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            listener.bind(UnixDomainSocketAddress.of(ending.socket()));
            Future<?> endsAtOnce = executor.submit(() -> {
                try (SocketChannel taken = listener.accept()) {
                    listener.close();
                    Files.delete(ending.socket());
                }
                return null;
            });
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            DaemonClient client = new DaemonClient(ending, CommandLineProcess.launch(), out, err);
            Path image = folder.resolve("replaced.png");
            try {
                assertEquals(ExitCodes.OK, client.run(renderArgs("scenes/aa-edges.json", image)), text(err));
                endsAtOnce.get(10, TimeUnit.SECONDS);
                assertTrue(text(err).contains("started a render daemon"), text(err));
                assertTrue(Files.size(image) > 0);
            } finally {
                client.run(List.of("stop"));
            }
        }
    }

    @Test
    void stopEndsTheDaemonAndRemovesItsSocket() throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        assertEquals(ExitCodes.OK, client(out, new ByteArrayOutputStream()).run(List.of("stop")));
        assertTrue(daemon.get(30, TimeUnit.SECONDS), "it served until stopped");
        assertFalse(Files.exists(address.socket()));
        assertEquals("stopped the render daemon", text(out).strip());
        ByteArrayOutputStream again = new ByteArrayOutputStream();
        assertEquals(ExitCodes.OK, client(again, new ByteArrayOutputStream()).run(List.of("stop")));
        assertTrue(text(again).contains("no render daemon serves"), text(again));
    }

    @Test
    void aSecondDaemonDoesNotServeTheSameSocket() throws Exception {
        assertFalse(RenderDaemon.serve(address, Duration.ofSeconds(1)), "the lock is held");
        renderStillWorks();
    }

    @Test
    void anIdleDaemonEnds() throws Exception {
        DaemonAddress idle = DaemonAddress.at(folder.resolve("idle.sock"));
        long start = System.nanoTime();
        assertTrue(RenderDaemon.serve(idle, Duration.ofMillis(300)));
        assertTrue(System.nanoTime() - start >= 300_000_000L);
        assertFalse(Files.exists(idle.socket()));
    }

    @Test
    void aRebuildEndsAnIdleDaemon() throws Exception {
        DaemonAddress rebuilt = DaemonAddress.at(folder.resolve("rebuilt.sock"));
        AtomicLong build = new AtomicLong(1);
        Future<Boolean> served =
                executor.submit(() -> RenderDaemon.serve(rebuilt, Duration.ofMinutes(1), build::get, 20));
        for (int i = 0; i < 500 && !Files.exists(rebuilt.socket()); i++) Thread.sleep(10);
        Thread.sleep(100);
        assertFalse(served.isDone(), "serving while the build is the same");
        build.set(2);
        assertTrue(served.get(10, TimeUnit.SECONDS));
        assertFalse(Files.exists(rebuilt.socket()));
    }

    @Test
    void daemonAnywhereButFirstIsAnError() {
        StringWriter err = new StringWriter();
        int code = RaytracerCli.run(
                new String[] {"render", "--daemon", "scenes/aa-edges.json"},
                new PrintWriter(new StringWriter()),
                new PrintWriter(err));
        assertEquals(ExitCodes.BAD_INPUT, code);
        code = RaytracerCli.run(
                new String[] {"--daemon", "render", "scenes/aa-edges.json"},
                new PrintWriter(new StringWriter()),
                new PrintWriter(err));
        assertEquals(ExitCodes.BAD_INPUT, code);
        assertTrue(err.toString().contains("--daemon must be the first argument"), err.toString());
    }

    @Test
    void aFolderOthersCanOpenIsRefused() throws Exception {
        Path shared = Files.createDirectory(folder.resolve("shared"));
        Files.setPosixFilePermissions(shared, PosixFilePermissions.fromString("rwxr-xr-x"));
        BadInputException e = assertThrows(BadInputException.class, () -> DaemonAddress.makePrivate(shared));
        assertTrue(e.getMessage().contains("rwx------") && e.getMessage().contains("rwxr-xr-x"), e.getMessage());
        Path made = folder.resolve("made");
        DaemonAddress.makePrivate(made);
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(made)));
    }

    @Test
    void theAddressIsPrivateShortAndKeyedByFolder() throws Exception {
        JavaLaunch launch = JavaLaunch.ofThisProgram();
        DaemonAddress here = DaemonAddress.in(folder, launch, Path.of("."));
        assertEquals(here, DaemonAddress.in(folder, launch, Path.of("").toAbsolutePath()), "one daemon per folder");
        assertFalse(here.equals(DaemonAddress.in(folder, launch, folder)), "another folder, another daemon");
        Path deep = Files.createDirectories(folder.resolve("d".repeat(100)));
        BadInputException e = assertThrows(BadInputException.class, () -> DaemonAddress.in(deep, launch, Path.of(".")));
        assertTrue(e.getMessage().contains("more than the 100"), e.getMessage());
    }

    /** Waits until a connection succeeds (the socket's file exists a moment before it listens). */
    private static void awaitListening(DaemonAddress daemonAddress) throws InterruptedException {
        for (int i = 0; i < 1000; i++) {
            try (SocketChannel probe = SocketChannel.open(UnixDomainSocketAddress.of(daemonAddress.socket()))) {
                return;
            } catch (IOException notYet) {
                Thread.sleep(10);
            }
        }
        throw new AssertionError("the daemon did not listen within 10 s at " + daemonAddress.socket());
    }

    private void renderStillWorks() throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Path image = folder.resolve("after.png");
        assertEquals(
                ExitCodes.OK,
                client(new ByteArrayOutputStream(), err).run(renderArgs("scenes/aa-edges.json", image)),
                text(err));
        assertTrue(Files.size(image) > 0);
        Files.delete(image);
    }

    /** A render of the street on one thread, with progress lines: seconds long. */
    private static List<String> slowRender(Path image) {
        return List.of("render", "scenes/street.json", "-o", image.toString(), "--threads", "1", "--progress", "lines");
    }

    private static List<String> renderArgs(String scene, Path image) {
        return List.of("render", scene, "-o", image.toString(), "--threads", "1", "--width", "64", "--height", "40");
    }

    private DaemonClient client(ByteArrayOutputStream out, ByteArrayOutputStream err) {
        return new DaemonClient(address, JavaLaunch.ofThisProgram(), out, err);
    }

    private static DaemonProtocol.Request request(List<String> args, String workingFolder) {
        return new DaemonProtocol.Request(DaemonProtocol.Kind.RENDER, workingFolder, false, args);
    }

    private record Answer(int code, String err) {}

    /** Sends a request at the protocol's level; with {@code cancel}, sends it once the render shows progress. */
    private Answer ask(List<String> args, String workingFolder, Byte cancel) throws IOException {
        try (SocketChannel channel = SocketChannel.open(StandardProtocolFamily.UNIX)) {
            channel.connect(UnixDomainSocketAddress.of(address.socket()));
            request(args, workingFolder).send(channel);
            StringBuilder err = new StringBuilder();
            assertEquals(
                    DaemonProtocol.RUNNING,
                    DaemonProtocol.readFrame(channel).kind(),
                    "the first frame says the request runs");
            if (cancel != null) {
                awaitProgress(channel, err);
                DaemonProtocol.writeFully(channel, ByteBuffer.wrap(new byte[] {cancel}));
            }
            while (true) {
                DaemonProtocol.Frame frame = DaemonProtocol.readFrame(channel);
                if (frame.kind() == DaemonProtocol.EXIT)
                    return new Answer(frame.body().getInt(), err.toString());
                if (frame.kind() == DaemonProtocol.ERR)
                    err.append(StandardCharsets.UTF_8.decode(frame.body()).toString());
            }
        }
    }

    private static void awaitProgress(SocketChannel channel, StringBuilder err) throws IOException {
        while (!err.toString().contains("render: 10%")) {
            DaemonProtocol.Frame frame = DaemonProtocol.readFrame(channel);
            assertTrue(frame.kind() != DaemonProtocol.EXIT, "the render ended before its first progress line: " + err);
            if (frame.kind() == DaemonProtocol.ERR)
                err.append(StandardCharsets.UTF_8.decode(frame.body()).toString());
        }
    }

    private static String text(ByteArrayOutputStream bytes) {
        return bytes.toString(StandardCharsets.UTF_8);
    }

    /** The statistics without the figures that differ between two renders of the same image (times, rates). */
    private static String withoutTimes(String output) {
        return output.replaceAll("[0-9.]+ s wall \\([0-9.]+ s preparing\\)", "T")
                .replaceAll("[0-9.]+ M rays/s", "R");
    }

    private static List<String> list(Path dir) throws IOException {
        try (var files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
