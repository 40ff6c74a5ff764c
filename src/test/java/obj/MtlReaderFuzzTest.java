package obj;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;

/**
 * Fuzzes the MTL reader: whatever the bytes, it returns materials that map onto valid core materials or throws
 * {@link ObjFormatException}; any other exception fails. {@code mvn test} replays the committed inputs in
 * {@code src/test/resources/obj/MtlReaderFuzzTestInputs/}; {@code JAZZER_FUZZ=1} fuzzes (see docs/CLI.md).
 */
class MtlReaderFuzzTest {
    @FuzzTest(maxDuration = "5m")
    void mtlText(byte[] data) {
        try {
            MtlLibrary library = MtlReader.parse("fuzz.mtl", new String(data, StandardCharsets.ISO_8859_1));
            for (MtlMaterial m : library.materials().values()) {
                m.toMaterial(); // what the reader returns must map onto a valid core material
                m.emission();
            }
        } catch (ObjFormatException expected) {
            // the declared error: fine
        }
    }
}
