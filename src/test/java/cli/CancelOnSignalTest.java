package cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
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
        CommandLineProcess.Ended process =
                CommandLineProcess.sigtermDuringStreetRender(List.of(), List.of(), image.toString());
        assertEquals(143, process.exitValue(), process.output());
        assertTrue(process.output().contains("render cancelled: no image written"), process.output());
        assertEquals(List.of(), list(out), "no image and no temporary file");
    }

    private static List<Path> list(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.toList();
        }
    }
}
