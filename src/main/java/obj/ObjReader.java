package obj;

import static obj.Tokens.abbreviate;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.LongSupplier;
import primitives.Limits;
import renderer.RenderMemory;

/**
 * Reads the geometry of a Wavefront OBJ file: {@code v} (vertices), {@code vn} (normals), {@code vt} (texture
 * coordinates), {@code f} (faces, any polygon, triangulated as a fan from its first corner), with 1-based or
 * negative (counted back from the latest) indices and {@code #} comments, and the materials: {@code mtllib}
 * (material libraries, read by the caller, see {@link MtlReader}) and {@code usemtl} (the material of the faces
 * that follow). Other statements ({@code o}, {@code g}, {@code s}, ...) are skipped with one warning per kind. A
 * malformed line, a zero or out-of-range index, or a file without faces is an {@link ObjFormatException} naming
 * file:line and the reason; nothing else escapes.
 *
 * <p>Indices must refer to elements defined on earlier lines (as every exporter writes them). Normals (texture
 * coordinates) are used for a material's faces only if every corner of them has one; otherwise they are dropped
 * with a warning (flat shading; no texture coordinates). {@link #readModel} gives one mesh per material;
 * {@link #read} one mesh of all faces.
 */
public final class ObjReader {
    /** What the skipped statements are, for the warnings; others are "not supported". */
    private static final Map<String, String> SKIPPED = Map.of(
            "vp", "parameter-space vertices are not supported",
            "o", "object names are not used",
            "g", "group names are not used",
            "s", "smoothing groups are not used (normals come from vn)",
            "l", "polylines are not supported",
            "p", "points are not supported");

    /** The statements read (besides the skipped ones): a line starting with one makes the file an OBJ file. */
    private static final java.util.Set<String> STATEMENTS = java.util.Set.of("v", "vn", "vt", "f", "usemtl", "mtllib");

    private final String file;
    private final DoubleList vertices = new DoubleList();
    private final DoubleList normals = new DoubleList();
    /** Per triangle corner: the vertex index and the normal index (-1 if none), 0-based. */
    private final IntList cornerVertices = new IntList();

    private final IntList cornerNormals = new IntList();
    /** Per triangle corner: the texture coordinate index (-1 if none), 0-based. */
    private final IntList cornerTexCoords = new IntList();
    /** u, v per {@code vt}. */
    private final DoubleList texCoords = new DoubleList();
    /** Per triangle: its material's index in {@link #materialNames}. */
    private final IntList triangleMaterials = new IntList();
    /** The {@code usemtl} names in order of first use; null for faces before any {@code usemtl}. */
    private final List<String> materialNames = new ArrayList<>();

    private final Map<String, Integer> materialIndex = new HashMap<>();
    private final List<ObjModel.Library> libraries = new ArrayList<>();
    /** The current material's index in {@link #materialNames}, -1 until a face or usemtl needs one. */
    private int currentMaterial = -1;
    /** The name the next faces take (null: before any usemtl). */
    private String pendingMaterial;

    private final Map<String, int[]> skipped = new LinkedHashMap<>();
    private final List<String> notes = new ArrayList<>();
    private int lineNumber;
    /** Whether faces are kept apart by material ({@link #readModel}) or all in one part ({@link #read}). */
    private boolean byMaterial;

    private ObjReader(String file, LongSupplier heap) {
        this.file = primitives.Printable.message(file); // it names the file in warnings and errors
        this.heap = heap;
        this.memoryBudget = heap.getAsLong();
    }

    /**
     * Reads an OBJ file as one mesh of all its faces; the path as given names it in messages.
     *
     * @param path the OBJ file
     * @return the triangles, normals and warnings read
     * @throws ObjFormatException if the file cannot be read, is malformed or has no faces
     */
    public static ObjMesh read(Path path) throws ObjFormatException {
        return read(path, path.toString());
    }

    /**
     * Reads an OBJ file that messages call {@code name} as one mesh of all its faces (materials not applied).
     *
     * @param path the OBJ file
     * @param name the file's name in messages and warnings
     * @return the triangles, normals and warnings read
     * @throws ObjFormatException if the file cannot be read, is malformed or has no faces
     */
    public static ObjMesh read(Path path, String name) throws ObjFormatException {
        return MeshAssembler.merged(readModel(path, name, RenderMemory::available, false));
    }

    /**
     * Reads an OBJ file that messages call {@code name} as one mesh per {@code usemtl} material, with the
     * {@code mtllib} references for the caller to read (it decides where files may be read from).
     *
     * @param path the OBJ file
     * @param name the file's name in messages and warnings
     * @return the parts, material libraries and warnings
     * @throws ObjFormatException if the file cannot be read, is malformed or has no faces
     */
    public static ObjModel readModel(Path path, String name) throws ObjFormatException {
        return readModel(path, name, RenderMemory::available, true);
    }

    private static ObjModel readModel(Path path, String name, LongSupplier heap, boolean byMaterial)
            throws ObjFormatException {
        if (Files.isDirectory(path)) throw new ObjFormatException(name, 0, "is a folder, not an OBJ file");
        if (Files.exists(path) && !Files.isRegularFile(path)) {
            throw new ObjFormatException(name, 0, "is not a regular file");
        }
        try (InputStream in = Files.newInputStream(path)) {
            return readModel(name, new InputStreamReader(in, StandardCharsets.ISO_8859_1), heap, byMaterial);
        } catch (NoSuchFileException e) {
            throw new ObjFormatException(name, 0, "file not found", e);
        } catch (IOException e) {
            throw new ObjFormatException(name, 0, "cannot be read: " + e, e);
        }
    }

    /**
     * Reads OBJ text; {@code name} names it in messages. The reader is not closed. Bytes are best read as
     * ISO-8859-1 (every byte is a character, so no decoding error can occur; OBJ is ASCII).
     *
     * @param name the text's name in messages and warnings
     * @param text the OBJ text
     * @return the triangles, normals and warnings read
     * @throws ObjFormatException if the text cannot be read, is malformed, too long or has no faces
     */
    public static ObjMesh read(String name, Reader text) throws ObjFormatException {
        return read(name, text, RenderMemory::available);
    }

    /** {@link #read(String, Reader)} against the heap {@code heap} reports (tests give a small one). */
    static ObjMesh read(String name, Reader text, LongSupplier heap) throws ObjFormatException {
        return MeshAssembler.merged(readModel(name, text, heap, false));
    }

    /**
     * Reads OBJ text held in a string as one mesh per material ({@link #readModel(Path, String)}).
     *
     * @param name the text's name in messages and warnings
     * @param text the whole OBJ text
     * @return the parts, material libraries and warnings
     * @throws ObjFormatException if the text is malformed, too long or has no faces
     */
    public static ObjModel parseModel(String name, String text) throws ObjFormatException {
        return readModel(name, new StringReader(text), RenderMemory::available, true);
    }

    /**
     * Reads OBJ text; {@code byMaterial} keeps the faces of each material apart (else: one part of all faces, and
     * usemtl and mtllib only checked).
     */
    private static ObjModel readModel(String name, Reader text, LongSupplier heap, boolean byMaterial)
            throws ObjFormatException {
        ObjReader reader = new ObjReader(name, heap);
        reader.byMaterial = byMaterial;
        // Bounded lines: a file without line breaks, or an endless one, is an error, not an out-of-memory crash.
        new BoundedLines(text, reader.file, "OBJ", MAX_LINE_LENGTH, MAX_CHARACTERS)
                .forEach(
                        name,
                        (line, number) -> {
                            reader.lineNumber = number;
                            reader.parseLine(line);
                        },
                        () -> reader.sawStatement);
        return reader.finish();
    }

    /**
     * Reads OBJ text held in a string.
     *
     * @param name the text's name in messages and warnings
     * @param text the whole OBJ text
     * @return the triangles, normals and warnings read
     * @throws ObjFormatException if the text is malformed, too long or has no faces
     */
    public static ObjMesh parse(String name, String text) throws ObjFormatException {
        return read(name, new StringReader(text));
    }

    /** Longest line read (characters): OBJ lines are short, a face of a thousand corners fits. */
    public static final int MAX_LINE_LENGTH = 1 << 16;
    /** Longest material name ({@code usemtl}, {@code newmtl}), so names cannot fill the heap. */
    public static final int MAX_NAME_LENGTH = 1024;
    /** Most materials ({@code usemtl} names that faces use) in one OBJ file; each becomes a mesh. */
    public static final int MAX_MATERIALS = 1 << 16;
    /** Longest OBJ text read (characters, about bytes): 2^31 - 1, the most a Java array can index. */
    public static final long MAX_CHARACTERS = Integer.MAX_VALUE;

    /**
     * Heap per triangle: the reader's corner and material lists and the mesh made of them (56 bytes), and the accelerator built
     * to render it ({@link RenderMemory#BYTES_PER_PRIMITIVE}). Checked while reading, so a mesh too large for the
     * heap stops with the figures at the line where it outgrew it, not with an out-of-memory crash.
     */
    public static final int BYTES_PER_TRIANGLE = 56 + RenderMemory.BYTES_PER_PRIMITIVE;
    /**
     * Heap per {@code v}, {@code vn} or {@code vt} line: the reader's list, the mesh's copies, the pairing of
     * positions, normals and texture coordinates into vertices.
     */
    public static final int BYTES_PER_VERTEX = 100;
    /** Elements (coordinates and corners) read between two checks of the size against the heap. */
    private static final int CHECK_EVERY = 1 << 16;

    /** Reports the heap the JVM can give (garbage counted as used until collected). */
    private final LongSupplier heap;
    /** The heap when reading began: what the mesh may need. */
    private long memoryBudget;

    private boolean budgetConfirmed;
    /** Elements read when the size is next checked. */
    private long nextSizeCheck = CHECK_EVERY;
    /**
     * Whether a line starting with an OBJ keyword was read: until then a bad line is reported without quoting it,
     * since the file may be any file of the machine rather than an OBJ file.
     */
    private boolean sawStatement;

    private void parseLine(String raw) throws ObjFormatException {
        int hash = raw.indexOf('#');
        String line = (hash >= 0 ? raw.substring(0, hash) : raw).strip();
        if (line.isEmpty()) return;
        String[] tokens = line.split("\\s+");
        String keyword = tokens[0];
        // A line that starts with an OBJ keyword makes the file an OBJ file: its tokens may then be quoted.
        if (STATEMENTS.contains(keyword) || SKIPPED.containsKey(keyword)) {
            sawStatement = true;
        }
        switch (keyword) {
            case "v" -> vertex(tokens);
            case "vn" -> normal(tokens);
            case "f" -> face(tokens);
            case "vt" -> textureCoordinate(tokens);
            case "usemtl" -> useMaterial(line.substring(keyword.length()).strip());
            case "mtllib" -> materialLibraries(tokens);
            default -> skip(keyword);
        }
        long elements = (long) vertices.size() + normals.size() + texCoords.size() + cornerVertices.size();
        if (elements >= nextSizeCheck) {
            checkSize();
            nextSizeCheck = elements + CHECK_EVERY;
        }
    }

    /**
     * Stops a mesh that outgrows what one mesh may hold ({@link Limits#MAX_PRIMITIVES} triangles or vertices) or
     * what the heap can give for it to be loaded and rendered.
     */
    private void checkSize() throws ObjFormatException {
        long triangles = cornerVertices.size() / 3;
        long points = (vertices.size() + normals.size()) / 3 + texCoords.size() / 2;
        if (triangles > Limits.MAX_PRIMITIVES || points > Limits.MAX_PRIMITIVES) {
            throw error(String.format(
                    Locale.ROOT,
                    "the mesh has %,d triangles and %,d vertices, normals and texture coordinates so far; one mesh"
                            + " may have at most %,d"
                            + " of each",
                    triangles,
                    points,
                    Limits.MAX_PRIMITIVES));
        }
        long bytes = triangles * BYTES_PER_TRIANGLE + points * BYTES_PER_VERTEX;
        if (bytes > memoryBudget && !budgetConfirmed) {
            // Garbage counted as used when reading began: collect it once and count what this reader holds.
            budgetConfirmed = true;
            System.gc();
            long held = 8L * (vertices.capacity() + normals.capacity() + texCoords.capacity())
                    + 4L
                            * (cornerVertices.capacity()
                                    + cornerNormals.capacity()
                                    + cornerTexCoords.capacity()
                                    + triangleMaterials.capacity());
            memoryBudget = Math.max(memoryBudget, heap.getAsLong() + held);
        }
        if (bytes > memoryBudget) {
            throw error(String.format(
                    Locale.ROOT,
                    "the mesh needs about %s of memory to load and render by this line (%,d triangles at %d"
                            + " bytes, %,d vertices, normals and texture coordinates at %d bytes), but this JVM could give %s; simplify"
                            + " the mesh or give Java more memory (-Xmx)",
                    RenderMemory.bytes(bytes),
                    triangles,
                    BYTES_PER_TRIANGLE,
                    points,
                    BYTES_PER_VERTEX,
                    RenderMemory.bytes(memoryBudget)));
        }
    }

    private void vertex(String[] tokens) throws ObjFormatException {
        int n = tokens.length - 1;
        // x y z, x y z w (w is a rational weight, irrelevant for polygons) or x y z r g b (vertex colours).
        if (n != 3 && n != 4 && n != 6) {
            throw error("'v' needs x y z (optionally w, or r g b), but has " + n + " value" + (n == 1 ? "" : "s"));
        }
        for (int i = 1; i <= n; i++) {
            double value = number(tokens[i], "v");
            if (i <= 3) vertices.add(value);
        }
        if (n > 3) note(n == 4 ? "vertex weights (the 4th 'v' value)" : "vertex colours (values 4 to 6 of 'v')");
    }

    private void normal(String[] tokens) throws ObjFormatException {
        int n = tokens.length - 1;
        if (n != 3) throw error("'vn' needs x y z, but has " + n + " value" + (n == 1 ? "" : "s"));
        for (int i = 1; i <= 3; i++) normals.add(number(tokens[i], "vn"));
    }

    private void textureCoordinate(String[] tokens) throws ObjFormatException {
        int n = tokens.length - 1;
        // u, u v or u v w (w is for 3D textures, unused).
        if (n < 1 || n > 3) throw error("'vt' needs u (optionally v and w), but has " + n + " values");
        double u = number(tokens[1], "vt");
        double v = n >= 2 ? number(tokens[2], "vt") : 0;
        if (n == 3) number(tokens[3], "vt");
        texCoords.add(u);
        texCoords.add(v);
    }

    private void useMaterial(String name) throws ObjFormatException {
        if (name.isEmpty()) throw error("'usemtl' needs a material name");
        if (name.length() > MAX_NAME_LENGTH) {
            throw error("'usemtl' name of " + name.length() + " characters; a material name may have at most "
                    + MAX_NAME_LENGTH);
        }
        pendingMaterial = name;
        currentMaterial = -1; // assigned by the next face, so a usemtl without faces makes no empty part
    }

    private void materialLibraries(String[] tokens) throws ObjFormatException {
        if (tokens.length < 2) throw error("'mtllib' needs at least one file name");
        for (int i = 1; i < tokens.length; i++) libraries.add(new ObjModel.Library(tokens[i], lineNumber));
    }

    /** The index of the material the current faces take, in order of first use. */
    private int material() throws ObjFormatException {
        if (currentMaterial < 0) {
            String name = byMaterial ? pendingMaterial : null;
            Integer index = materialIndex.get(name);
            if (index == null) {
                // Each material becomes a mesh of its own: bounded, so a file cannot make millions of tiny ones.
                if (materialNames.size() >= MAX_MATERIALS) {
                    throw error("the faces use more than " + MAX_MATERIALS + " materials (usemtl names), the most"
                            + " one OBJ file may use here");
                }
                index = materialNames.size();
                materialNames.add(name);
                materialIndex.put(name, index);
            }
            currentMaterial = index;
        }
        return currentMaterial;
    }

    private void face(String[] tokens) throws ObjFormatException {
        int n = tokens.length - 1;
        if (n < 3) throw error("'f' needs at least 3 corners, but has " + n);
        int[] v = new int[n];
        int[] vt = new int[n];
        int[] vn = new int[n];
        for (int i = 0; i < n; i++) {
            String corner = tokens[i + 1];
            String[] parts = corner.split("/", -1);
            if (parts.length > 3 || parts[0].isEmpty()) {
                throw error("face corner '" + abbreviate(corner) + "' must be v, v/vt, v//vn or v/vt/vn");
            }
            v[i] = resolve(parts[0], vertices.size() / 3, "vertex", corner);
            vt[i] = parts.length >= 2 && !parts[1].isEmpty()
                    ? resolve(parts[1], texCoords.size() / 2, "texture coordinate", corner)
                    : -1;
            vn[i] = parts.length == 3 && !parts[2].isEmpty()
                    ? resolve(parts[2], normals.size() / 3, "normal", corner)
                    : -1;
        }
        int material = material();
        for (int i = 1; i + 1 < n; i++) { // fan from the first corner
            addCorner(v[0], vt[0], vn[0]);
            addCorner(v[i], vt[i], vn[i]);
            addCorner(v[i + 1], vt[i + 1], vn[i + 1]);
            triangleMaterials.add(material);
        }
    }

    private void addCorner(int vertex, int texCoord, int normal) {
        cornerVertices.add(vertex);
        cornerTexCoords.add(texCoord);
        cornerNormals.add(normal);
    }

    /** A 1-based or negative OBJ index as a 0-based index into the {@code count} elements defined so far. */
    private int resolve(String token, int count, String what, String corner) throws ObjFormatException {
        int index;
        try {
            index = Integer.parseInt(token);
        } catch (NumberFormatException e) {
            throw error("face corner '" + abbreviate(corner) + "': " + what + " index '" + abbreviate(token)
                    + "' is not an integer");
        }
        String allowed = count == 0
                ? "no " + what + " is defined before this line"
                : "allowed are 1.." + count + ", or -1..-" + count + " counting back from the latest";
        if (index == 0) {
            throw error("face corner '" + abbreviate(corner) + "': " + what
                    + " index 0 is invalid: OBJ indices start at 1 (" + allowed + ")");
        }
        int resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0 || resolved >= count) {
            throw error("face corner '" + abbreviate(corner) + "': " + what + " index " + index + " is out of range: "
                    + count + " defined before this line (" + allowed + ")");
        }
        return resolved;
    }

    private double number(String token, String keyword) throws ObjFormatException {
        return Tokens.finite(token, keyword, file, lineNumber);
    }

    private void skip(String keyword) throws ObjFormatException {
        // (parseLine has set sawStatement for every known keyword, so before it an unknown one is no OBJ file.)
        if (!keyword.matches("[A-Za-z_][A-Za-z0-9_]*") || !sawStatement) {
            throw error(
                    sawStatement
                            ? "'" + abbreviate(keyword) + "' is not an OBJ statement (a line starts with a keyword such"
                                    + " as v, vn or f)"
                            : "does not start like an OBJ file: its first statement is not one (a line starts with a"
                                    + " keyword such as v, vn, f, o or g)");
        }
        skipped.computeIfAbsent(keyword, k -> new int[] {0, lineNumber})[0]++;
    }

    /** Records a warning once, however often its cause occurs. */
    private void note(String what) {
        String text = what + " are ignored";
        if (!notes.contains(text)) notes.add(text);
    }

    private ObjModel finish() throws ObjFormatException {
        if (cornerVertices.size() == 0) {
            throw new ObjFormatException(file, 0, "has no faces ('f' lines): a mesh needs at least one triangle");
        }
        List<String> warnings = new ArrayList<>();
        for (Map.Entry<String, int[]> e : skipped.entrySet()) {
            int count = e.getValue()[0];
            warnings.add(file + ": skipped " + count + " '" + e.getKey() + "' statement" + (count == 1 ? "" : "s")
                    + " (first at line " + e.getValue()[1] + "): "
                    + SKIPPED.getOrDefault(e.getKey(), "not supported"));
        }
        for (String note : notes) warnings.add(file + ": " + note);
        if (!byMaterial && (pendingMaterial != null || !libraries.isEmpty())) {
            warnings.add(file + ": materials (mtllib, usemtl) are not applied here: all faces form one mesh");
        }
        MeshAssembler assembler = new MeshAssembler(
                file,
                vertices,
                normals,
                texCoords,
                cornerVertices,
                cornerNormals,
                cornerTexCoords,
                triangleMaterials,
                materialNames);
        List<ObjMesh> parts = assembler.parts(warnings);
        return new ObjModel(parts, libraries, warnings);
    }

    private ObjFormatException error(String reason) {
        return new ObjFormatException(file, lineNumber, reason);
    }
}
