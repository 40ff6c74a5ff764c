package cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A scene that searches no tree never loads the Vector API: its classes take tens of milliseconds to load and
 * initialise in a new JVM, which a command-line render of a small scene would wait for (docs/ACCURACY.md, "Against
 * POV-Ray"). The POV-Ray comparison's scene (a plane and one sphere) is rendered by the command line in a JVM of its own,
 * with the module, and the JVM's class-loading log must name no class of it.
 */
class VectorApiOnDemandTest {
    @TempDir
    Path out;

    @Test
    void aSceneWithoutATreeRendersWithoutLoadingTheVectorApi() throws Exception {
        Path log = out.resolve("classes.log");
        Process process = CommandLineProcess.builder(
                        List.of("--add-modules", "jdk.incubator.vector", "-Xlog:class+load=info:file=" + log),
                        "render",
                        "scenes/povray/soft-shadow.json",
                        "-o",
                        out.resolve("soft-shadow.png").toString(),
                        "--threads",
                        "1",
                        "--target-error",
                        "4")
                .redirectErrorStream(true)
                .start();
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(process.waitFor(60, TimeUnit.SECONDS), "the render ended");
        assertEquals(0, process.exitValue(), output);
        // The JVM had the module, and the log is the render's: so an absent class was not loaded, not unlogged.
        assertTrue(output.contains("jdk.incubator.vector"), "the JVM ran with the Vector API module:\n" + output);
        List<String> loaded = Files.readAllLines(log, StandardCharsets.UTF_8);
        assertTrue(
                loaded.stream().anyMatch(line -> line.contains(" geometries.Accelerator ")), "the log lists classes");
        assertEquals(
                List.of(),
                loaded.stream()
                        .filter(line -> line.contains(" jdk.incubator.vector."))
                        .limit(5)
                        .toList(),
                "Vector API classes loaded by a render that searches no tree");
    }
}
