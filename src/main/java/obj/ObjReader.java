package obj;

import java.io.BufferedReader;
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
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.LongSupplier;
import primitives.Limits;
import renderer.RenderMemory;

/**
 * Reads the geometry of a Wavefront OBJ file: {@code v} (vertices), {@code vn} (normals) and {@code f} (faces,
 * any polygon, triangulated as a fan from its first corner), with 1-based or negative (counted back from the
 * latest) indices and {@code #} comments. Other statements ({@code vt}, {@code o}, {@code g}, {@code s},
 * {@code usemtl}, ...) are skipped with one warning per kind. A malformed {@code v}, {@code vn} or {@code f} line,
 * a zero or out-of-range index, or a file without faces is an {@link ObjFormatException} naming file:line and
 * the reason; nothing else escapes.
 *
 * <p>Indices must refer to elements defined on earlier lines (as every exporter writes them). Normals are used
 * only if every face corner has one; a mesh where some corners lack them is flat-shaded (with a warning).
 */
public final class ObjReader {
    /** What the skipped statements are, for the warnings; others are "not supported". */
    private static final Map<String, String> SKIPPED = Map.of(
            "vt", "texture coordinates are not used",
            "vp", "parameter-space vertices are not supported",
            "o", "object names are not used",
            "g", "group names are not used",
            "s", "smoothing groups are not used (normals come from vn)",
            "usemtl", "OBJ materials are not used (the scene file assigns the material)",
            "mtllib", "OBJ material libraries are not used (the scene file assigns the material)",
            "l", "polylines are not supported",
            "p", "points are not supported");

    private final String file;
    private final DoubleList vertices = new DoubleList();
    private final DoubleList normals = new DoubleList();
    /** Per triangle corner: the vertex index and the normal index (-1 if none), 0-based. */
    private final IntList cornerVertices = new IntList();

    private final IntList cornerNormals = new IntList();
    private final Map<String, int[]> skipped = new LinkedHashMap<>();
    private final List<String> notes = new ArrayList<>();
    private int textureCoordinates;
    private int lineNumber;

    private ObjReader(String file, LongSupplier heap) {
        this.file = primitives.Printable.message(file); // it names the file in warnings and errors
        this.heap = heap;
        this.memoryBudget = heap.getAsLong();
    }

    /**
     * Reads an OBJ file; the path as given names it in messages.
     *
     * @param path the OBJ file
     * @return the triangles, normals and warnings read
     * @throws ObjFormatException if the file cannot be read, is malformed or has no faces
     */
    public static ObjMesh read(Path path) throws ObjFormatException {
        return read(path, path.toString());
    }

    /**
     * Reads an OBJ file that messages call {@code name}.
     *
     * @param path the OBJ file
     * @param name the file's name in messages and warnings
     * @return the triangles, normals and warnings read
     * @throws ObjFormatException if the file cannot be read, is malformed or has no faces
     */
    public static ObjMesh read(Path path, String name) throws ObjFormatException {
        if (Files.isDirectory(path)) throw new ObjFormatException(name, 0, "is a folder, not an OBJ file");
        if (Files.exists(path) && !Files.isRegularFile(path)) {
            throw new ObjFormatException(name, 0, "is not a regular file");
        }
        try (InputStream in = Files.newInputStream(path)) {
            return read(name, new InputStreamReader(in, StandardCharsets.ISO_8859_1));
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
        ObjReader reader = new ObjReader(name, heap);
        try {
            BufferedReader lines = new BufferedReader(text);
            StringBuilder line = new StringBuilder();
            while (readLine(lines, line, reader)) reader.parseLine(line.toString());
        } catch (IOException e) {
            throw new ObjFormatException(name, reader.lineNumber, "cannot be read: " + e, e);
        }
        return reader.finish();
    }

    /**
     * Reads the next line into {@code line} (without its terminator) and counts it; false at the end of the text.
     * Lines are bounded ({@link #MAX_LINE_LENGTH}) and so is the whole text ({@link #MAX_CHARACTERS}): a file
     * without line breaks, or an endless one, is an error, not an out-of-memory crash.
     */
    private static boolean readLine(BufferedReader in, StringBuilder line, ObjReader reader)
            throws IOException, ObjFormatException {
        line.setLength(0);
        int c = in.read();
        if (c < 0) return false;
        reader.lineNumber++;
        while (c >= 0 && c != '\n') {
            if (++reader.characters > MAX_CHARACTERS) {
                throw reader.error("the file is longer than " + MAX_CHARACTERS + " characters, the most an OBJ"
                        + " file may have here");
            }
            if (c != '\r') line.append((char) c);
            if (line.length() > MAX_LINE_LENGTH) {
                throw reader.error(
                        reader.sawStatement
                                ? "line longer than " + MAX_LINE_LENGTH + " characters"
                                : "line longer than " + MAX_LINE_LENGTH
                                        + " characters before any OBJ statement: this is not an OBJ file");
            }
            c = in.read();
        }
        return true;
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
    /** Longest OBJ text read (characters, about bytes): 2^31 - 1, the most a Java array can index. */
    public static final long MAX_CHARACTERS = Integer.MAX_VALUE;

    /**
     * Heap per triangle: the reader's corner lists and the mesh made of them (40 bytes), and the accelerator built
     * to render it ({@link RenderMemory#BYTES_PER_PRIMITIVE}). Checked while reading, so a mesh too large for the
     * heap stops with the figures at the line where it outgrew it, not with an out-of-memory crash.
     */
    public static final int BYTES_PER_TRIANGLE = 40 + RenderMemory.BYTES_PER_PRIMITIVE;
    /** Heap per {@code v} or {@code vn} line: the reader's list, the mesh's copies, the vertex-normal pairing. */
    public static final int BYTES_PER_VERTEX = 100;
    /** Elements (coordinates and corners) read between two checks of the size against the heap. */
    private static final int CHECK_EVERY = 1 << 16;

    /** Characters read so far. */
    private long characters;
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
        if (keyword.equals("v") || keyword.equals("vn") || keyword.equals("f") || SKIPPED.containsKey(keyword)) {
            sawStatement = true;
        }
        switch (keyword) {
            case "v" -> vertex(tokens);
            case "vn" -> normal(tokens);
            case "f" -> face(tokens);
            default -> skip(keyword);
        }
        long elements = (long) vertices.size() + normals.size() + cornerVertices.size();
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
        long triangles = cornerVertices.size() / 3, points = (vertices.size() + normals.size()) / 3;
        if (triangles > Limits.MAX_PRIMITIVES || points > Limits.MAX_PRIMITIVES) {
            throw error(String.format(
                    Locale.ROOT,
                    "the mesh has %,d triangles and %,d vertices and normals so far; one mesh may have at most %,d"
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
            long held = 8L * (vertices.capacity() + normals.capacity())
                    + 4L * (cornerVertices.capacity() + cornerNormals.capacity());
            memoryBudget = Math.max(memoryBudget, heap.getAsLong() + held);
        }
        if (bytes > memoryBudget) {
            throw error(String.format(
                    Locale.ROOT,
                    "the mesh needs about %s of memory to load and render by this line (%,d triangles at %d"
                            + " bytes, %,d vertices and normals at %d bytes), but this JVM could give %s; simplify"
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

    private void face(String[] tokens) throws ObjFormatException {
        int n = tokens.length - 1;
        if (n < 3) throw error("'f' needs at least 3 corners, but has " + n);
        int[] v = new int[n];
        int[] vn = new int[n];
        for (int i = 0; i < n; i++) {
            String corner = tokens[i + 1];
            String[] parts = corner.split("/", -1);
            if (parts.length > 3 || parts[0].isEmpty()) {
                throw error("face corner '" + abbreviate(corner) + "' must be v, v/vt, v//vn or v/vt/vn");
            }
            v[i] = resolve(parts[0], vertices.size() / 3, "vertex", corner);
            if (parts.length >= 2 && !parts[1].isEmpty()) {
                // Texture coordinates are not used, but the index must still be well formed.
                resolve(parts[1], textureCoordinates, "texture coordinate", corner);
            }
            vn[i] = parts.length == 3 && !parts[2].isEmpty()
                    ? resolve(parts[2], normals.size() / 3, "normal", corner)
                    : -1;
        }
        for (int i = 1; i + 1 < n; i++) { // fan from the first corner
            addCorner(v[0], vn[0]);
            addCorner(v[i], vn[i]);
            addCorner(v[i + 1], vn[i + 1]);
        }
    }

    private void addCorner(int vertex, int normal) {
        cornerVertices.add(vertex);
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
        double value;
        try {
            value = Double.parseDouble(token);
        } catch (NumberFormatException e) {
            throw error("'" + keyword + "' value '" + abbreviate(token) + "' is not a number");
        }
        if (!Double.isFinite(value)) {
            throw error("'" + keyword + "' value '" + abbreviate(token) + "' must be a finite number");
        }
        return value;
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
        if (keyword.equals("vt")) textureCoordinates++;
        skipped.computeIfAbsent(keyword, k -> new int[] {0, lineNumber})[0]++;
    }

    /** Records a warning once, however often its cause occurs. */
    private void note(String what) {
        String text = what + " are ignored";
        if (!notes.contains(text)) notes.add(text);
    }

    private ObjMesh finish() throws ObjFormatException {
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

        int corners = cornerVertices.size();
        boolean allNormals = true;
        for (int i = 0; i < corners && allNormals; i++) {
            int n = cornerNormals.get(i);
            allNormals = n >= 0 && !normals.isZero(n);
        }
        if (!allNormals) {
            if (normals.size() > 0) {
                warnings.add(
                        file + ": normals ignored (flat shading): some face corners have no normal or a zero" + " one");
            }
            return new ObjMesh(vertices.toArray(), cornerVertices.toArray(), null, warnings);
        }
        // OBJ indexes positions and normals separately; a mesh has one normal per vertex: one vertex per pair.
        Map<Long, Integer> pairs = new HashMap<>();
        DoubleList v = new DoubleList(), n = new DoubleList();
        int[] indices = new int[corners];
        for (int i = 0; i < corners; i++) {
            int vi = cornerVertices.get(i), ni = cornerNormals.get(i);
            long key = ((long) vi << 32) | ni;
            Integer index = pairs.get(key);
            if (index == null) {
                index = pairs.size();
                pairs.put(key, index);
                for (int k = 0; k < 3; k++) {
                    v.add(vertices.get(3 * vi + k));
                    n.add(normals.get(3 * ni + k));
                }
            }
            indices[i] = index;
        }
        return new ObjMesh(v.toArray(), indices, n.toArray(), warnings);
    }

    private ObjFormatException error(String reason) {
        return new ObjFormatException(file, lineNumber, reason);
    }

    /** Input quoted in a message: escaped (no terminal control sequences) and short. */
    private static String abbreviate(String s) {
        return primitives.Printable.of(s.length() <= 20 ? s : s.substring(0, 20) + "...");
    }

    /** Twice the capacity, without overflowing (the size checks stop a mesh long before the array limit). */
    private static int grown(int capacity) {
        return (int) Math.min(Integer.MAX_VALUE - 8, 2L * capacity);
    }

    /** A growable double array: OBJ files hold millions of values, which boxed lists would triple in size. */
    private static final class DoubleList {
        private double[] data = new double[48];
        private int size;

        void add(double value) {
            if (size == data.length) data = Arrays.copyOf(data, grown(size));
            data[size++] = value;
        }

        double get(int i) {
            return data[i];
        }

        boolean isZero(int triple) {
            return data[3 * triple] == 0 && data[3 * triple + 1] == 0 && data[3 * triple + 2] == 0;
        }

        int size() {
            return size;
        }

        int capacity() {
            return data.length;
        }

        double[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }

    /** A growable int array. */
    private static final class IntList {
        private int[] data = new int[48];
        private int size;

        void add(int value) {
            if (size == data.length) data = Arrays.copyOf(data, grown(size));
            data[size++] = value;
        }

        int get(int i) {
            return data[i];
        }

        int size() {
            return size;
        }

        int capacity() {
            return data.length;
        }

        int[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }
}
