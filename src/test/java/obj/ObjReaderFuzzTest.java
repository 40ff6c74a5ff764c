package obj;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;

/**
 * Fuzzes the OBJ reader (one mesh, and one mesh per material): whatever the bytes, it returns meshes that the core
 * accepts or throws {@link ObjFormatException}; any other exception fails. {@code mvn test} replays the committed inputs in
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

    /** The same for the reader of meshes per material ({@code usemtl}, {@code vt}): every part a valid mesh. */
    @FuzzTest(maxDuration = "5m")
    void objModel(byte[] data) {
        try {
            ObjModel model = ObjReader.parseModel("fuzz.obj", new String(data, StandardCharsets.ISO_8859_1));
            for (ObjMesh part : model.parts()) part.toMesh(true);
        } catch (ObjFormatException expected) {
            // the declared error: fine
        }
    }
}
