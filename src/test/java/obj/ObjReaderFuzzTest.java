package obj;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;

/**
 * Fuzzes the OBJ reader: whatever the bytes, it returns a mesh that the core accepts or throws
 * {@link ObjFormatException}; any other exception fails. {@code mvn test} replays the committed inputs in
 * {@code src/test/resources/obj/ObjReaderFuzzTestInputs/}; {@code JAZZER_FUZZ=1} fuzzes (see docs/CLI.md).
 */
class ObjReaderFuzzTest {
    @FuzzTest(maxDuration = "5m")
    void objText(byte[] data) {
        try {
            ObjMesh mesh = ObjReader.parse("fuzz.obj", new String(data, StandardCharsets.ISO_8859_1));
            mesh.toMesh(true); // what the reader returns must be a valid core mesh
        } catch (ObjFormatException expected) {
            // the declared error: fine
        }
    }
}
