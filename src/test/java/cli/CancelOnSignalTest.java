package cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The command line cancels cleanly on SIGTERM (what Ctrl-C's SIGINT does too): a render of the street, stopped a
 * few seconds in, says so on stderr, exits with the signal's status, and leaves neither the image nor a temporary
 * file in the output folder.
 */
class CancelOnSignalTest {
    @TempDir
    Path out;

    @Test
    void sigtermCancelsTheRenderAndWritesNothing() throws Exception {
        Path image = out.resolve("street.png");
        Process process = CommandLineProcess.builder(
                        List.of(),
                        "render",
                        "scenes/street.json",
                        "-o",
                        image.toString(),
                        "--threads",
                        "1",
                        "--progress",
                        "lines")
                .redirectErrorStream(true)
                .start();
        // Wait until the render has started (the first progress line), then send SIGTERM.
        StringBuilder output = new StringBuilder();
        var reader = process.inputReader(StandardCharsets.UTF_8);
        for (String line = reader.readLine(); line != null; line = reader.readLine()) {
            output.append(line).append('\n');
            if (line.startsWith("render:")) break;
        }
        process.toHandle().destroy(); // SIGTERM (Process.destroy would also close our end of its output)
        for (String line = reader.readLine(); line != null; line = reader.readLine())
            output.append(line).append('\n');
        assertTrue(process.waitFor(30, TimeUnit.SECONDS), "the process ended");
        assertEquals(143, process.exitValue(), output.toString());
        assertTrue(output.toString().contains("render cancelled: no image written"), output.toString());
        assertEquals(List.of(), list(out), "no image and no temporary file");
    }

    private static List<Path> list(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.toList();
        }
    }
}
