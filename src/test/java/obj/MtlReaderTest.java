package obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Color;
import primitives.Double3;
import primitives.Material;

/** The MTL reader: statements, the mapping onto {@link Material}, warnings and errors with file and line. */
class MtlReaderTest {
    private static MtlMaterial only(String text) throws ObjFormatException {
        MtlLibrary library = MtlReader.parse("m.mtl", text);
        assertEquals(1, library.materials().size());
        return library.materials().values().iterator().next();
    }

    private static Material material(String statements) throws ObjFormatException {
        return only("newmtl m\n" + statements).toMaterial();
    }

    @Test
    void plainPhongValuesMapDirectly() throws ObjFormatException {
        MtlMaterial m = only("# comment\nnewmtl red\nKa 0.1 0.2 0.3\nKd 0.8 0.1 0.1\nKs 0.5\nNs 96.4\nillum 2\n");
        assertEquals("red", m.name());
        assertEquals(2, m.line());
        Material material = m.toMaterial();
        assertEquals(new Double3(0.1, 0.2, 0.3), material.getKa());
        assertEquals(new Double3(0.8, 0.1, 0.1), material.getKd());
        assertEquals(new Double3(0.5), material.getKs(), "one value is grey");
        assertEquals(96, material.getShininess());
        assertEquals(Double3.ZERO, material.getKr());
        assertEquals(Double3.ZERO, material.getKt());
        assertEquals(1, material.getIndexOfRefraction());
        assertEquals(Color.BLACK, m.emission());
        assertNull(material.getKdMap());
    }

    @Test
    void unsetValuesKeepTheLibraryDefaults() throws ObjFormatException {
        Material material = material("");
        assertEquals(Double3.ONE, material.getKa());
        assertEquals(Double3.ZERO, material.getKd());
        assertEquals(0, material.getShininess());
    }

    @Test
    void illuminationModelsDecideMirrorAndRefraction() throws ObjFormatException {
        String base = "Kd 0.5 0.5 0.5\nKs 0.4 0.3 0.2\nNi 1.5\n";
        assertEquals(Double3.ZERO, material(base + "illum 1\n").getKs(), "illum 1: no highlight");
        assertEquals(new Double3(0.4, 0.3, 0.2), material(base + "illum 2\n").getKs());
        for (int illum : new int[] {3, 4, 5, 8}) {
            Material m = material(base + "illum " + illum + "\n");
            assertEquals(new Double3(0.4, 0.3, 0.2), m.getKr(), "illum " + illum + " reflects by Ks");
            assertEquals(1, m.getIndexOfRefraction(), "illum " + illum + " does not bend light");
        }
        for (int illum : new int[] {6, 7}) {
            Material m = material(base + "illum " + illum + "\n");
            assertEquals(new Double3(0.4, 0.3, 0.2), m.getKr());
            assertEquals(1.5, m.getIndexOfRefraction(), "illum " + illum + " refracts by Ni");
        }
        for (int illum : new int[] {0, 1, 2, 9, 10}) {
            assertEquals(Double3.ZERO, material(base + "illum " + illum + "\n").getKr(), "illum " + illum);
        }
    }

    @Test
    void illumZeroIsUnlitColour() throws ObjFormatException {
        MtlMaterial m = only("newmtl flat\nKd 1 0.5 0\nillum 0\n");
        Material material = m.toMaterial();
        assertEquals(Double3.ZERO, material.getKd());
        assertEquals(Double3.ZERO, material.getKa());
        assertEquals(new Color(255, 127.5, 0), m.emission());
    }

    @Test
    void emissionIsKeTimes255() throws ObjFormatException {
        assertEquals(new Color(255, 51, 0), only("newmtl lamp\nKe 1 0.2 0\n").emission());
    }

    @Test
    void dissolveMakesTheSurfacePartlyClearAndScalesDiffuse() throws ObjFormatException {
        Material m = material("Kd 0.8 0.4 0.2\nKa 0.5\nd 0.25\n");
        assertEquals(new Double3(0.75), m.getKt());
        assertEquals(new Double3(0.2, 0.1, 0.05), m.getKd());
        assertEquals(new Double3(0.125), m.getKa());
        // Tr is the complement of d; the later statement wins.
        assertEquals(new Double3(0.25), material("d 0.2\nTr 0.25\n").getKt());
        assertEquals(Double3.ZERO, material("d 1\n").getKt());
    }

    @Test
    void mapKdWithClampAndSkippedOptions() throws ObjFormatException {
        MtlMaterial m = only("newmtl t\nmap_Kd -clamp on -s 2 2 1 -o 0.5 textures/my wood.png\n");
        assertEquals(new MtlMaterial.TextureMap("textures/my wood.png", true, 2), m.mapKd());
        MtlLibrary library = MtlReader.parse("m.mtl", "newmtl t\nmap_Kd -bm 0.5 wood.png\nmap_Kd -bm 2 w.png\n");
        MtlMaterial t = library.materials().get("t");
        assertEquals(new MtlMaterial.TextureMap("w.png", false, 3), t.mapKd());
        assertEquals(List.of("m.mtl: texture option '-bm' is not supported (skipped)"), library.warnings());
    }

    @Test
    void unsupportedStatementsWarnOncePerKind() throws ObjFormatException {
        MtlLibrary library = MtlReader.parse(
                "w.mtl",
                "newmtl a\nTf 1 1 1\nmap_Bump b.png\nPr 0.5\nnewmtl b\nTf 1 1 1\nPr 0.2\nnewmtl a\nKd 1 0 0\n");
        assertEquals(
                List.of(
                        "w.mtl: skipped 2 'Tf' statements (first at line 2): the transmission filter is not used (kT"
                                + " comes from d)",
                        "w.mtl: skipped 1 'map_Bump' statement (first at line 3): bump maps are not supported",
                        "w.mtl: skipped 2 'Pr' statements (first at line 4): not supported",
                        "w.mtl: material \"a\" is defined again at line 8; the later definition is used"),
                library.warnings());
        assertEquals(new Double3(1, 0, 0), library.materials().get("a").kd());
        assertEquals(List.of("a", "b"), List.copyOf(library.materials().keySet()));
    }

    @Test
    void badStatementsNameFileLineAndWhatIsAllowed() {
        String[][] cases = {
            {"newmtl a\nKd 1 2\n", "bad.mtl:2: 'Kd' needs r g b (or one value for grey), but has 2 values"},
            {"newmtl a\nKd 1 x 1\n", "bad.mtl:2: 'Kd' value 'x' is not a number"},
            {"newmtl a\nKs -1 0 0\n", "bad.mtl:2: 'Ks' values must be 0 or more (1 is full), but one was negative"},
            {"newmtl a\nKd spectral r.spd\n", "bad.mtl:2: 'Kd spectral' is not supported: give r g b values (0 to 1)"},
            {"newmtl a\nKe NaN 0 0\n", "bad.mtl:2: 'Ke' value 'NaN' must be a finite number"},
            {"newmtl a\n\nNs 20000\n", "bad.mtl:3: 'Ns' value 20000 is out of range: allowed are 0 to 10000"},
            {"newmtl a\nNi 0\n", "bad.mtl:2: 'Ni' value 0 is out of range: allowed are 0.001 to 1000"},
            {"newmtl a\nd 1.5\n", "bad.mtl:2: 'd' value 1.5 is out of range: allowed are 0 (clear) to 1 (opaque)"},
            {"newmtl a\nd\n", "bad.mtl:2: 'd' needs one value, but has 0"},
            {"newmtl a\nillum 11\n", "bad.mtl:2: 'illum' needs one illumination model, an integer 0 to 10"},
            {"newmtl a\nillum 2.5\n", "bad.mtl:2: 'illum' needs one illumination model"},
            {"newmtl a\nmap_Kd\n", "bad.mtl:2: 'map_Kd' needs an image file name"},
            {"newmtl a\nmap_Kd -clamp maybe x.png\n", "bad.mtl:2: 'map_Kd -clamp' needs on or off"},
            {"newmtl a\nmap_Kd -nope x.png\n", "bad.mtl:2: 'map_Kd' option '-nope' is not a texture option"},
            {"Kd 1 1 1\n", "bad.mtl:1: 'Kd' before any 'newmtl'"},
            {"newmtl\n", "bad.mtl:1: 'newmtl' needs a material name"},
            {
                "newmtl " + "n".repeat(1025) + "\n",
                "bad.mtl:1: 'newmtl' name of 1025 characters; a material name may" + " have at most 1024"
            },
            {"newmtl a\n3d 1\n", "bad.mtl:2: '3d' is not an MTL statement"},
            {"# only a comment\n", "bad.mtl: has no materials ('newmtl' lines)"},
            {"root:x:0:0:root:/root:/bin/bash\n", "bad.mtl:1: does not start like an MTL file"},
        };
        for (String[] c : cases) {
            ObjFormatException e = assertThrows(ObjFormatException.class, () -> MtlReader.parse("bad.mtl", c[0]), c[0]);
            assertTrue(e.getMessage().startsWith(c[1]), c[0] + " -> " + e.getMessage());
        }
        // A file that is not MTL is not quoted.
        ObjFormatException e =
                assertThrows(ObjFormatException.class, () -> MtlReader.parse("x.mtl", "secret-token value\n"));
        assertTrue(!e.getMessage().contains("secret"), e.getMessage());
    }

    @Test
    void longLinesAndControlCharactersAreSafe() {
        ObjFormatException e = assertThrows(
                ObjFormatException.class,
                () -> MtlReader.parse("l.mtl", "newmtl a\nKd " + "1".repeat(MtlReader.MAX_LINE_LENGTH + 1) + "\n"));
        assertEquals(2, e.getLine());
        e = assertThrows(ObjFormatException.class, () -> MtlReader.parse("c.mtl", "newmtl a\nKd \u001b[2J 1 1\n"));
        assertTrue(!e.getMessage().contains("\u001b"), e.getMessage());
    }

    @Test
    void filesAreReadAndMissingOnesNamed(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("ok.mtl");
        Files.writeString(file, "newmtl a\r\nKd 0.5 0.5 0.5\r\n");
        assertEquals(
                new Double3(0.5),
                MtlReader.read(file, "ok.mtl").materials().get("a").kd());
        ObjFormatException e =
                assertThrows(ObjFormatException.class, () -> MtlReader.read(dir.resolve("no.mtl"), "no.mtl"));
        assertEquals("no.mtl: file not found", e.getMessage());
        e = assertThrows(ObjFormatException.class, () -> MtlReader.read(dir, "dir.mtl"));
        assertEquals("dir.mtl: is a folder, not an MTL file", e.getMessage());
    }
}
