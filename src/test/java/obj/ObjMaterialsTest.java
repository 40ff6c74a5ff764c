package obj;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** OBJ texture coordinates, {@code usemtl} and {@code mtllib}: parts per material, de-indexing, errors. */
class ObjMaterialsTest {
    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

    @Test
    void facesAreGroupedByMaterialInOrderOfFirstUse() throws ObjFormatException {
        String text = "mtllib a.mtl b.mtl\n" + SQUARE + "f 1 2 3\nusemtl red\nf 1/1 2/2 3/3\nusemtl blue\n"
                + "f 1/1 3/3 4/4\nusemtl red\nf 3/3 4/4 1/1\nusemtl unused\n";
        ObjModel model = ObjReader.parseModel("g.obj", text);
        assertEquals(List.of(new ObjModel.Library("a.mtl", 1), new ObjModel.Library("b.mtl", 1)), model.libraries());
        assertEquals(3, model.parts().size(), "a usemtl without faces makes no part");
        ObjMesh none = model.parts().get(0),
                red = model.parts().get(1),
                blue = model.parts().get(2);
        assertNull(none.material());
        assertEquals("red", red.material());
        assertEquals("blue", blue.material());
        assertEquals(1, none.triangleCount());
        assertEquals(2, red.triangleCount());
        assertEquals(1, blue.triangleCount());
        assertNull(none.texCoords(), "faces without vt");
        // Each part holds only the vertices it uses, with the texture coordinates of its corners.
        assertEquals(4, red.vertexCount());
        assertEquals(3, blue.vertexCount());
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, red.vertices(), 0);
        assertArrayEquals(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, red.texCoords(), 0);
        assertArrayEquals(new int[] {0, 1, 2, 2, 3, 0}, red.indices());
        assertTrue(model.warnings().isEmpty(), model.warnings().toString());
    }

    @Test
    void aPositionWithTwoTextureCoordinatesBecomesTwoVertices() throws ObjFormatException {
        // A seam: corner 1 has texture coordinate 1 in one face and 3 in the other.
        ObjMesh mesh = ObjReader.parse("seam.obj", SQUARE + "f 1/1 2/2 3/3\nf 1/3 3/3 4/4\n");
        assertEquals(5, mesh.vertexCount());
        assertArrayEquals(new double[] {0, 0, 1, 0, 1, 1, 1, 1, 0, 1}, mesh.texCoords(), 0);
        assertEquals(mesh.vertices()[0], mesh.vertices()[9], "the same position twice");
    }

    @Test
    void texCoordsWithOneOrThreeValues() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nvt 1 0 0\nf 1/1 2/2 3/1\n");
        assertArrayEquals(new double[] {0.5, 0, 1, 0, 0.5, 0}, mesh.texCoords(), 0);
    }

    @Test
    void someCornersWithoutTexCoordsDropThemWithAWarning() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("part.obj", SQUARE + "f 1/1 2/2 3/3\nf 1 3 4\n");
        assertNull(mesh.texCoords());
        assertEquals(
                List.of("part.obj: texture coordinates ignored (texture maps show one texel): some face corners have"
                        + " none"),
                mesh.warnings());
    }

    @Test
    void readMergesTheMaterialsIntoOneMesh() throws ObjFormatException {
        ObjMesh mesh = ObjReader.parse("m.obj", SQUARE + "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n");
        assertEquals(2, mesh.triangleCount());
        assertNull(mesh.material());
        assertEquals(
                List.of("m.obj: materials (mtllib, usemtl) are not applied here: all faces form one mesh"),
                mesh.warnings());
    }

    @Test
    void manyMaterialSwitchesStayFast() throws ObjFormatException {
        // 20,000 materials of one triangle each: grouping must not cost materials x triangles (4 * 10^8 steps).
        StringBuilder text = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        for (int i = 0; i < 20_000; i++) text.append("usemtl m").append(i).append("\nf 1 2 3\n");
        long start = System.nanoTime();
        ObjModel model = ObjReader.parseModel("many.obj", text.toString());
        assertEquals(20_000, model.parts().size());
        assertEquals("m19999", model.parts().get(19_999).material());
        assertTrue(System.nanoTime() - start < 5_000_000_000L, "took " + (System.nanoTime() - start) / 1e9 + " s");
    }

    @Test
    void theNumberOfMaterialsIsBounded() {
        StringBuilder text = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        for (int i = 0; i <= ObjReader.MAX_MATERIALS; i++)
            text.append("usemtl m").append(i).append("\nf 1 2 3\n");
        ObjFormatException e =
                assertThrows(ObjFormatException.class, () -> ObjReader.parseModel("many.obj", text.toString()));
        assertEquals(3 + 2 * ObjReader.MAX_MATERIALS + 2, e.getLine());
        assertTrue(e.getReason().startsWith("the faces use more than 65536 materials"), e.getMessage());
        StringBuilder mtl = new StringBuilder();
        for (int i = 0; i <= MtlReader.MAX_MATERIALS; i++)
            mtl.append("newmtl m").append(i).append('\n');
        e = assertThrows(ObjFormatException.class, () -> MtlReader.parse("many.mtl", mtl.toString()));
        assertEquals("many.mtl:65537: more than 65536 materials, the most an MTL file may have here", e.getMessage());
    }

    @Test
    void badTextureAndMaterialStatementsNameTheLine() {
        String[][] cases = {
            {
                SQUARE + "f 1/5 2/2 3/3\n",
                "b.obj:9: face corner '1/5': texture coordinate index 5 is out of range: 4"
                        + " defined before this line (allowed are 1..4, or -1..-4 counting back from the latest)"
            },
            {
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2 3\n",
                "b.obj:4: face corner '1/1': texture coordinate index 1 is out"
                        + " of range: 0 defined before this line (no texture coordinate is defined before this line)"
            },
            {SQUARE + "f 1/0 2 3\n", "b.obj:9: face corner '1/0': texture coordinate index 0 is invalid"},
            {SQUARE + "f 1/x 2 3\n", "b.obj:9: face corner '1/x': texture coordinate index 'x' is not an integer"},
            {"vt\n", "b.obj:1: 'vt' needs u (optionally v and w), but has 0 values"},
            {"vt 1 2 3 4\n", "b.obj:1: 'vt' needs u (optionally v and w), but has 4 values"},
            {"vt 1 inf\n", "b.obj:1: 'vt' value 'inf' is not a number"},
            {"vt 1 1e999\n", "b.obj:1: 'vt' value '1e999' must be a finite number"},
            {"v 0 0 0\nusemtl\n", "b.obj:2: 'usemtl' needs a material name"},
            {"mtllib\n", "b.obj:1: 'mtllib' needs at least one file name"},
            {
                "usemtl " + "n".repeat(1025) + "\n",
                "b.obj:1: 'usemtl' name of 1025 characters; a material name may have" + " at most 1024"
            },
        };
        for (String[] c : cases) {
            ObjFormatException e =
                    assertThrows(ObjFormatException.class, () -> ObjReader.parseModel("b.obj", c[0]), c[0]);
            assertTrue(e.getMessage().startsWith(c[1]), c[0] + " -> " + e.getMessage());
        }
    }
}
