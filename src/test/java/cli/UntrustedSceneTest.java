package cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Scene files from strangers, through the command line (docs/CLI.md, "Security model"): every case ends with exit
 * code 2 and one clear line, or renders correctly where the input is legal; nothing is written outside the output
 * path; no content of a file that is not a valid input is quoted; control characters never reach the terminal.
 */
class UntrustedSceneTest {
    private static final String CAMERA = "\"camera\": {\"location\": [0, -10, 0], \"lookAt\": [0, 0, 0],"
            + " \"vpDistance\": 10, \"vpWidth\": 4, \"vpHeight\": 4}";
    private static final String SECRET = "root:x:0:0:SECRET-CONTENT:/root:/bin/bash\n";

    @TempDir
    Path dir;

    private record Result(int code, String out, String err) {}

    private Result render(String json, String... extra) throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Path scene = Files.writeString(scenes.resolve("scene.json"), json);
        String[] args = Stream.concat(Stream.of("render", scene.toString(), "-q"), Stream.of(extra))
                .toArray(String[]::new);
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = RaytracerCli.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(code, out.toString(), err.toString());
    }

    private static String scene(String render, String geometries) {
        return "{" + CAMERA + ", \"render\": {" + render + "}, \"geometries\": [" + geometries + "]}";
    }

    private static void assertBadInput(Result r, String expected) {
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertTrue(r.err().startsWith("error: "), r.err());
        assertEquals(1, r.err().strip().lines().count(), "one line: " + r.err());
        assertTrue(r.err().contains(expected), "expected '" + expected + "' in: " + r.err());
        assertFalse(r.err().contains("SECRET"), "file content quoted: " + r.err());
        assertTrue(r.err().chars().noneMatch(c -> c < 0x20 && c != '\n'), "control characters: " + r.err());
    }

    @Test
    void aSceneNameCannotSendTheDefaultOutputElsewhere() throws IOException {
        Path cwd = Path.of("").toAbsolutePath();
        for (String name : List.of("../../x", "a/b", "..", ".hidden", "nul\u0000here", "esc\u001b[31mred", "")) {
            String json = "{\"name\": \"" + name.replace("\u0000", "\\u0000").replace("\u001b", "\\u001b") + "\", "
                    + scene("\"width\": 2, \"height\": 2", "").substring(1);
            Result r = render(json);
            assertBadInput(r, name.isEmpty() ? "" : "scene name");
            assertFalse(Files.exists(cwd.resolve("../x.png").normalize()), "nothing written above images/");
        }
    }

    @Test
    void referencedFilesMustStayInTheScenesFolderTree() throws IOException {
        Path outside = Files.writeString(dir.resolve("passwd"), SECRET);
        Path obj = Files.writeString(dir.resolve("cube.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Files.createDirectories(dir.resolve("scenes"));
        Path link = dir.resolve("scenes/link.obj");
        Files.createSymbolicLink(link, obj);
        for (String file : List.of("../passwd", "../cube.obj", "link.obj", "../../../../../../etc/hostname")) {
            Result r = render(scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"" + file + "\"}"));
            assertBadInput(r, file.endsWith("hostname") && !Files.exists(Path.of("/etc/hostname")) ? "" : "outside");
        }
        // --allow-path widens it: the linked mesh renders.
        Path png = dir.resolve("ok.png");
        Result allowed = render(
                scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"link.obj\"}"),
                "--allow-path",
                dir.toString(),
                "-o",
                png.toString());
        assertEquals(ExitCodes.OK, allowed.code(), allowed.err());
        assertTrue(Files.exists(png));
        assertTrue(Files.exists(outside));
    }

    @Test
    void whetherAFileExistsOutsideCannotBeLearnt() throws IOException {
        Files.writeString(dir.resolve("exists.obj"), SECRET);
        Files.createDirectories(dir.resolve("scenes"));
        Files.createSymbolicLink(dir.resolve("scenes/a.obj"), dir.resolve("exists.obj"));
        Files.createSymbolicLink(dir.resolve("scenes/b.obj"), dir.resolve("missing.obj"));
        String[] messages = new String[4];
        String[] files = {"../exists.obj", "../missing.obj", "a.obj", "b.obj"};
        for (int i = 0; i < files.length; i++) {
            Result r = render(
                    scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"" + files[i] + "\"}"));
            assertBadInput(r, "leads outside the scene file's folder");
            messages[i] =
                    r.err().replace(files[i], "F").replace("exists.obj", "X").replace("missing.obj", "X");
        }
        assertEquals(messages[0], messages[1], "the same answer for a file that exists and one that does not");
        assertEquals(messages[2], messages[3], "the same through links");
    }

    @Test
    void warningsFromAFileAreEscaped() throws IOException {
        Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(
                dir.resolve("scenes/m\u001b[31m.obj"), "o \u001b[2Jname\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Path png = dir.resolve("w.png");
        Result r = render(
                scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"m\\u001b[31m.obj\"}"),
                "-o",
                png.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(r.err().contains("m\\u001b[31m.obj: skipped 1 'o' statement"), r.err());
        assertTrue(r.err().chars().noneMatch(c -> c < 0x20 && c != '\n'), "control characters: " + r.err());
    }

    @Test
    void aFileThatIsNotAnObjIsNotQuoted() throws IOException {
        Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(dir.resolve("scenes/secret.obj"), SECRET);
        Files.writeString(dir.resolve("scenes/escape.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \u001b[2J\n");
        Result secret = render(scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"secret.obj\"}"));
        assertBadInput(secret, "does not start like an OBJ file");
        Result escape = render(scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"escape.obj\"}"));
        assertBadInput(escape, "\\u001b");
    }

    @Test
    void aSceneFileThatIsNotJsonIsNotQuoted() throws IOException {
        assertBadInput(render(SECRET), "is not a JSON scene file");
        // A raw ESC is malformed JSON; an escaped one in a key reaches the message, escaped again.
        assertBadInput(render("{\"na\u001bme\": 1}"), "malformed JSON");
        assertBadInput(render("{\"na\\u001bme\": 1}"), "unknown field \"na\\u001bme\"");
    }

    @Test
    void devicesAndHugeFilesAreRefusedBeforeReading() throws IOException {
        StringWriter out = new StringWriter(), err = new StringWriter();
        if (Files.exists(Path.of("/dev/zero"))) {
            int code = RaytracerCli.run(
                    new String[] {"render", "/dev/zero"}, new PrintWriter(out, true), new PrintWriter(err, true));
            assertEquals(ExitCodes.BAD_INPUT, code, err.toString());
            assertTrue(err.toString().contains("not a regular file"), err.toString());
        }
        Files.createDirectories(dir.resolve("scenes"));
        Path noLines = dir.resolve("scenes/long.obj");
        Files.writeString(noLines, "v" + " 1".repeat(40_000) + "\n");
        Result r = render(scene("\"width\": 2, \"height\": 2", "{\"type\": \"mesh\", \"file\": \"long.obj\"}"));
        assertBadInput(r, "line longer than 65536 characters");
    }

    @Test
    void resourceLimitsAreCheckedBeforeAnyWork() throws IOException {
        assertBadInput(
                render(scene("\"width\": 2, \"height\": 2, \"maxLevel\": 1000", "")), "maxLevel must be in [1, 256]");
        if (Runtime.getRuntime().maxMemory() < 16384L * 16384 * 28) {
            // The documented maximum of 2^28 pixels needs 7.5 GB; where the heap is smaller it is refused with what
            // it needs (a JVM with that much heap would render it, which this test does not wait for).
            assertBadInput(
                    render(scene("\"width\": 16384, \"height\": 16384", "")),
                    "$.render: the render needs about 7.5 GB of memory (the 16384 x 16384 image 7.5 GB at 28 bytes"
                            + " per pixel");
        }
        assertBadInput(render(scene("\"width\": 16385, \"height\": 16384", "")), "at most 2^28 pixels");
        Result lights = render("{" + CAMERA + ", \"render\": {\"width\": 2, \"height\": 2}, \"lights\": [{\"type\":"
                + " \"point\", \"position\": [0, 0, 5], \"color\": [1, 1, 1], \"radius\": 1, \"samples\":"
                + " 1000000000}]}");
        assertBadInput(lights, "must be in [1, 1048576], but was 1000000000");
        String tooMany = "must be in [1, 1048576], but was 1048577";
        assertBadInput(
                render(scene("\"width\": 2, \"height\": 2, \"antiAliasing\": {\"samples\": 1048577}", "")), tooMany);
        assertBadInput(render(scene("\"width\": 2, \"height\": 2, \"glossySamples\": 1048577", "")), tooMany);
        String lens = CAMERA.replace(
                "}", ", \"depthOfField\": {\"focalDistance\": 10, \"aperture\": 1, \"samples\":" + " 1048577}}");
        assertBadInput(render("{" + lens + ", \"render\": {\"width\": 2, \"height\": 2}}"), tooMany);
        assertBadInput(
                render(scene("\"width\": 2, \"height\": 2", ""), "--samples", "1048577"), "--samples " + tooMany);
        assertBadInput(
                render(scene("\"width\": 2, \"height\": 2", ""), "--width", "2000000000"),
                "--width must be in [1, 268435456], but was 2000000000");
        assertBadInput(render(scene("\"width\": 2, \"height\": 2", ""), "--height", "0"), "--height must be in [1, ");
        assertBadInput(
                render(scene("\"width\": 2, \"height\": 2", ""), "--light-cutoff", "NaN"),
                "--light-cutoff must be in [0, 255]");
    }

    @Test
    void tooManyThreadsAreRefusedWithTheAllowedRange() throws IOException {
        int max = Math.min(256, 4 * Runtime.getRuntime().availableProcessors());
        String range = "must be in [1, " + max + "] (4 per processor x "
                + Runtime.getRuntime().availableProcessors() + " processors, at most 256), but was 3000";
        assertBadInput(render(scene("\"width\": 4, \"height\": 4, \"threads\": 3000", "")), "threads " + range);
        assertBadInput(render(scene("\"width\": 4, \"height\": 4", ""), "--threads", "3000"), "--threads " + range);
        // The largest allowed count renders.
        Path png = dir.resolve("t.png");
        Result ok = render(scene("\"width\": 4, \"height\": 4, \"threads\": " + max, ""), "-o", png.toString());
        assertEquals(ExitCodes.OK, ok.code(), ok.err());
    }

    @Test
    void twoPerfectMirrorsAtTheDeepestLevelRender() throws IOException {
        String mirrors =
                "{\"type\": \"plane\", \"point\": [0, 0, -1], \"normal\": [0, 0, 1], \"material\": {\"kR\": 1}},"
                        + " {\"type\": \"plane\", \"point\": [0, 0, 1], \"normal\": [0, 0, 1], \"material\": {\"kR\": 1}}";
        String json = "{\"camera\": {\"location\": [0, 0, 0], \"direction\": [0.001, 0, 1], \"up\": [1, 0, 0],"
                + " \"vpDistance\": 1, \"vpWidth\": 1, \"vpHeight\": 1}, \"render\": {\"width\": 4, \"height\": 4,"
                + " \"maxLevel\": 256, \"threads\": 1}, \"geometries\": [" + mirrors + "]}";
        Path png = dir.resolve("mirrors.png");
        Result r = render(json, "-o", png.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(Files.exists(png));
    }

    @Test
    void outputNamesThatNoFileSystemTakesAreRefusedBeforeRendering() throws IOException {
        Result r = render(
                scene("\"width\": 2, \"height\": 2", ""),
                "-o",
                dir.resolve("x".repeat(252) + ".png").toString());
        assertBadInput(r, "longer than 255 bytes");
        Path fits = dir.resolve("y".repeat(251) + ".png"); // 255 characters: renders, through a short temporary name
        Result ok = render(scene("\"width\": 2, \"height\": 2", ""), "-o", fits.toString());
        assertEquals(ExitCodes.OK, ok.code(), ok.err());
        assertTrue(Files.exists(fits));
    }

    @Test
    void negativeBenchmarkRunsAreBadInput() {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = RaytracerCli.run(
                new String[] {"benchmark", "planning", "-5"}, new PrintWriter(out, true), new PrintWriter(err, true));
        assertEquals(ExitCodes.BAD_INPUT, code, err.toString());
        assertTrue(err.toString().contains("runs must be in [1, 1000], but was -5"), err.toString());
    }
}
