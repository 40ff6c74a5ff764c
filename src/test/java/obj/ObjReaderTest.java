package obj;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** OBJ import: the statements read, the ones skipped, and every malformed line rejected with file:line. */
class ObjReaderTest {
    private static final String SQUARE = """
            # a unit square as one quad
            v 0 0 0
            v 1 0 0
            v 1 1 0   # trailing comment
            v 0 1 0
            f 1 2 3 4
            """;

    @Test
    void quadIsTriangulatedAsAFan() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("square.obj", SQUARE);
        assertEquals(4, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, mesh.indices());
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, mesh.vertices());
        assertNull(mesh.normals());
        assertTrue(mesh.warnings().isEmpty(), mesh.warnings().toString());
        assertEquals(2, mesh.toMesh(true).triangleCount());
    }

    @Test
    void negativeIndicesCountBackFromTheLatestVertex() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -1 -2\n");
        assertArrayEquals(new int[] {0, 1, 2, 0, 3, 2}, mesh.indices());
    }

    @Test
    void normalsGiveOneVertexPerPositionNormalPair() throws ObjFormatException {
        String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 2\nf 1//1 2//1 3//1\nf 1//2 3//1 2//1\n";
        ObjMesh mesh = ObjReader.parse("n.obj", text);
        // (1,1) (2,1) (3,1) and then (1,2) is new: four vertices.
        assertEquals(4, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 3, 2, 1}, mesh.indices());
        assertArrayEquals(new double[] {0, 0, 2}, java.util.Arrays.copyOfRange(mesh.normals(), 9, 12));
    }

    @Test
    void cornersWithoutNormalsMeanFlatShadingWithAWarning() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3\n");
        assertNull(mesh.normals());
        assertEquals(1, mesh.warnings().size());
        assertTrue(
                mesh.warnings().get(0).contains("flat shading"), mesh.warnings().toString());
    }

    @Test
    void textureIndicesAreReadAndUnsupportedStatementsWarnOncePerKind() throws ObjFormatException {
        String text = "mtllib a.mtl\no cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\ng side\n"
                + "usemtl red\ns 1\nf 1/1 2/2 3/3\nf 1/1/ 2/2/ 3/3/\n";
        ObjMesh mesh = ObjReader.parse("tex.obj", text);
        assertEquals(2, mesh.triangleCount());
        assertArrayEquals(new double[] {0, 0, 1, 0, 0, 1}, mesh.texCoords());
        assertEquals(4, mesh.warnings().size(), mesh.warnings().toString());
        assertTrue(mesh.warnings().get(1).startsWith("tex.obj: skipped 1 'g' statement (first at line 9)"));
        assertEquals(
                "tex.obj: materials (mtllib, usemtl) are not applied here: all faces form one mesh",
                mesh.warnings().get(3));
    }

    @Test
    void missingFileNamesTheFile(@TempDir Path dir) {
        Path missing = dir.resolve("nope.obj");
        ObjFormatException e = assertThrows(ObjFormatException.class, () -> ObjReader.read(missing));
        assertEquals(missing.toString() + ": file not found", e.getMessage());
        assertEquals(0, e.getLine());
    }

    @Test
    void readsAFile(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("sq.obj"), SQUARE);
        assertEquals(2, ObjReader.read(file).triangleCount());
        ObjFormatException e = assertThrows(ObjFormatException.class, () -> ObjReader.read(dir));
        assertTrue(e.getMessage().contains("is a folder"), e.getMessage());
    }

    @Test
    void zeroIndexIsRejectedWithFileLineAndWhatIsAllowed() {
        ObjFormatException e = assertThrows(
                ObjFormatException.class, () -> ObjReader.parse("z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"));
        assertEquals(4, e.getLine());
        assertEquals(
                "z.obj:4: face corner '0': vertex index 0 is invalid: OBJ indices start at 1"
                        + " (allowed are 1..3, or -1..-3 counting back from the latest)",
                e.getMessage());
    }

    @Test
    void outOfRangeIndicesAreRejected() {
        ObjFormatException high = assertThrows(
                ObjFormatException.class, () -> ObjReader.parse("h.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"));
        assertTrue(high.getMessage().startsWith("h.obj:4: face corner '4': vertex index 4 is out of range"));
        ObjFormatException low = assertThrows(
                ObjFormatException.class, () -> ObjReader.parse("l.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"));
        assertTrue(low.getMessage().contains("vertex index -4 is out of range"), low.getMessage());
        ObjFormatException normal = assertThrows(
                ObjFormatException.class, () -> ObjReader.parse("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2 3\n"));
        assertTrue(normal.getMessage().contains("normal index 1 is out of range"), normal.getMessage());
        assertTrue(normal.getMessage().contains("no normal is defined before this line"), normal.getMessage());
    }

    @Test
    void malformedLinesAreRejectedWithTheReason() {
        String[][] cases = {
            {"v 1 2\n", "1: 'v' needs x y z (optionally w, or r g b), but has 2 values"},
            {"v 1 2 x\n", "1: 'v' value 'x' is not a number"},
            {"v 1 2 NaN\n", "1: 'v' value 'NaN' must be a finite number"},
            {"v 1 2 1e999\n", "1: 'v' value '1e999' must be a finite number"},
            {"vn 1 2\n", "1: 'vn' needs x y z, but has 2 values"},
            {"v 0 0 0\nf 1 1\n", "2: 'f' needs at least 3 corners, but has 2"},
            {"v 0 0 0\nf 1 a 1\n", "2: face corner 'a': vertex index 'a' is not an integer"},
            {"v 0 0 0\nf 1/1/1/1 1 1\n", "2: face corner '1/1/1/1' must be v, v/vt, v//vn or v/vt/vn"},
            {"v 0 0 0\nf /1 1 1\n", "2: face corner '/1' must be v, v/vt, v//vn or v/vt/vn"},
            {"1.0 2.0 3.0\n", "1: does not start like an OBJ file"},
            {"v 0 0 0\n1.0 2.0 3.0\n", "2: '1.0' is not an OBJ statement"},
            {"# only a comment\n", ": has no faces ('f' lines): a mesh needs at least one triangle"},
        };
        for (String[] c : cases) {
            ObjFormatException e = assertThrows(ObjFormatException.class, () -> ObjReader.parse("m.obj", c[0]), c[0]);
            assertTrue(e.getMessage().startsWith("m.obj" + (c[1].startsWith(":") ? "" : ":") + c[1]), e.getMessage());
        }
    }

    @Test
    void windowsLineEndingsAndTabsAreFine() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("crlf.obj", "v\t0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
        assertEquals(1, mesh.triangleCount());
    }

    @Test
    void aMeshTooLargeForTheHeapStopsWithTheFiguresAtItsLine() throws ObjFormatException {
        // 100,000 triangles need about 22 MB at 216 bytes each: with 5 MB to give, reading stops on the way.
        String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n".repeat(100_000);
        ObjFormatException e = assertThrows(
                ObjFormatException.class, () -> ObjReader.read("big.obj", new StringReader(text), () -> 5_000_000));
        assertTrue(e.getLine() > 3 && e.getLine() < 100_003, e.getMessage());
        assertTrue(
                e.getReason().startsWith("the mesh needs about ")
                        && e.getReason().contains(" of memory to load and render by this line (")
                        && e.getReason()
                                .contains(
                                        " triangles at 216 bytes, 3 vertices, normals and texture coordinates at 100 bytes),"
                                                + " but"
                                                + " this JVM could give "),
                e.getMessage());
        // With the heap to spare, the same text reads.
        assertEquals(
                100_000,
                ObjReader.read("big.obj", new StringReader(text), () -> 1_000_000_000L)
                        .triangleCount());
    }

    @Test
    void controlCharactersFromTheFileOrItsNameAreEscaped() {
        ObjFormatException e = assertThrows(
                ObjFormatException.class, () -> ObjReader.parse("\u001b]0;x.obj", "v 0 0 0\nf 1 1 \u001b[2J\n"));
        assertTrue(e.getMessage().startsWith("\\u001b]0;x.obj:2: face corner '\\u001b[2J'"), e.getMessage());
        assertTrue(e.getMessage().chars().noneMatch(c -> c < 0x20), e.getMessage());
    }
}
