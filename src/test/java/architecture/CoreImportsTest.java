package architecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The core packages import nothing outside the JDK and the core itself: Jackson, picocli and the progress bar
 * are for the tool packages (sceneio, obj, cli) only. Reads the sources, so it also catches a fully qualified
 * use that no import line shows.
 */
class CoreImportsTest {
    private static final Path SOURCES = Path.of("src/main/java");
    private static final List<String> CORE = List.of("primitives", "geometries", "lighting", "scene", "renderer");
    private static final Set<String> ALLOWED_ROOTS =
            Set.of("java", "javax", "primitives", "geometries", "lighting", "scene", "renderer");
    /** A JDK module too (incubating): the BVH's vectorized box test and binning use it when the JVM has it. */
    private static final String VECTOR_API = "jdk.incubator.vector.";

    private static final Pattern IMPORT = Pattern.compile("^import\\s+(?:static\\s+)?([\\w.]+)", Pattern.MULTILINE);
    /**
     * Fully qualified names of the third-party libraries and the scene-file package. (The tool packages cli, obj
     * and app are caught by the import check: their names are too common as variables to search for.)
     */
    private static final Pattern FORBIDDEN = Pattern.compile(
            "\\b(com\\.fasterxml|picocli|me\\.tongfei|org\\.jline|com\\.code_intelligence|sceneio)\\.\\w");

    static List<Path> coreSources() throws IOException {
        List<Path> files = new ArrayList<>();
        for (String pkg : CORE) {
            try (Stream<Path> walk = Files.walk(SOURCES.resolve(pkg))) {
                walk.filter(p -> p.toString().endsWith(".java")).forEach(files::add);
            }
        }
        return files;
    }

    @Test
    void corePackagesUseOnlyTheJdkAndEachOther() throws IOException {
        List<Path> files = coreSources();
        assertTrue(files.size() > 20, "the core sources were found: " + files.size());
        List<String> violations = new ArrayList<>();
        for (Path file : files) {
            String source = Files.readString(file);
            Matcher imports = IMPORT.matcher(source);
            while (imports.find()) {
                String root = imports.group(1).split("\\.")[0];
                boolean jdkModule = imports.group(1).startsWith(VECTOR_API);
                if (!ALLOWED_ROOTS.contains(root) && !jdkModule) violations.add(file + " imports " + imports.group(1));
            }
            Matcher forbidden = FORBIDDEN.matcher(source.replaceAll("(?s)/\\*.*?\\*/|//[^\\n]*", ""));
            while (forbidden.find()) violations.add(file + " uses " + forbidden.group());
        }
        assertEquals(List.of(), violations);
    }

    @Test
    void theCheckWouldCatchAViolation() {
        Matcher m = FORBIDDEN.matcher("Object o = com.fasterxml.jackson.databind.ObjectMapper.class;");
        assertTrue(m.find());
        Matcher i = IMPORT.matcher("package x;\nimport picocli.CommandLine;\n");
        assertTrue(i.find());
        assertEquals("picocli.CommandLine", i.group(1));
    }
}
