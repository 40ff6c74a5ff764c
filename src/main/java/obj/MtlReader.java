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
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import primitives.Double3;

/**
 * Reads a Wavefront MTL (material library) file: {@code newmtl} and, per material, {@code Kd Ks Ka Ke} (r [g b],
 * 0 or more), {@code Ns} (0 to 10,000), {@code Ni} (0.001 to 1000), {@code d} or {@code Tr} (0 to 1),
 * {@code illum} (0 to 10) and {@code map_Kd} (an image, with {@code -clamp on|off}; other options skipped). Other
 * statements (other maps, {@code Tf}, PBR extensions, ...) are skipped with one warning per kind. A malformed
 * line, a statement before any {@code newmtl} or a file without materials is an {@link ObjFormatException}
 * naming file:line and the reason; nothing else escapes. How the values become a material: {@link MtlMaterial}.
 */
public final class MtlReader {
    /** Longest line read (characters), as for OBJ files. */
    public static final int MAX_LINE_LENGTH = ObjReader.MAX_LINE_LENGTH;
    /** Most materials in one MTL file, as many as one OBJ file may use. */
    public static final int MAX_MATERIALS = ObjReader.MAX_MATERIALS;
    /** Longest MTL text read (characters): 16 MiB, far more than the largest material libraries. */
    public static final long MAX_CHARACTERS = 1 << 24;

    /** What the skipped statements are, for the warnings; others are "not supported". */
    private static final Map<String, String> SKIPPED = Map.ofEntries(
            Map.entry("Tf", "the transmission filter is not used (kT comes from d)"),
            Map.entry("sharpness", "reflection-map sharpness is not used"),
            Map.entry("map_Ka", "ambient maps are not supported"),
            Map.entry("map_Ks", "specular maps are not supported"),
            Map.entry("map_Ke", "emission maps are not supported"),
            Map.entry("map_Ns", "shininess maps are not supported"),
            Map.entry("map_d", "opacity maps are not supported"),
            Map.entry("map_Bump", "bump maps are not supported"),
            Map.entry("map_bump", "bump maps are not supported"),
            Map.entry("bump", "bump maps are not supported"),
            Map.entry("disp", "displacement maps are not supported"),
            Map.entry("decal", "decal maps are not supported"),
            Map.entry("refl", "reflection maps are not supported (illum 3 to 8 reflect the scene)"),
            Map.entry("norm", "normal maps are not supported"));
    /** Statements this reader understands. */
    private static final Set<String> STATEMENTS =
            Set.of("newmtl", "Kd", "Ks", "Ka", "Ke", "Ns", "Ni", "d", "Tr", "illum", "map_Kd");
    /** Texture options and how many values each takes (o, s, t take 1 to 3 numbers). */
    private static final Map<String, Integer> MAP_OPTIONS = Map.ofEntries(
            Map.entry("-blendu", 1),
            Map.entry("-blendv", 1),
            Map.entry("-bm", 1),
            Map.entry("-boost", 1),
            Map.entry("-cc", 1),
            Map.entry("-clamp", 1),
            Map.entry("-imfchan", 1),
            Map.entry("-mm", 2),
            Map.entry("-o", 3),
            Map.entry("-s", 3),
            Map.entry("-t", 3),
            Map.entry("-texres", 1),
            Map.entry("-type", 1));

    private final String file;
    private final Map<String, MtlMaterial> materials = new LinkedHashMap<>();
    private final Map<String, int[]> skipped = new LinkedHashMap<>();
    private final List<String> notes = new ArrayList<>();
    private int lineNumber;
    private boolean sawStatement;
    /** The material being read; its fields are written into a record when the next begins or the file ends. */
    private String name;

    private int nameLine;
    private Double3 kd, ks, ka, ke;
    private Double ns, ni, dissolve;
    private Integer illum;
    private MtlMaterial.TextureMap mapKd;

    private MtlReader(String file) {
        this.file = primitives.Printable.message(file);
    }

    /**
     * Reads an MTL file that messages call {@code name}.
     *
     * @param path the MTL file
     * @param name the file's name in messages and warnings
     * @return the materials and warnings
     * @throws ObjFormatException if the file is missing, cannot be read, is malformed or has no materials
     */
    public static MtlLibrary read(Path path, String name) throws ObjFormatException {
        if (Files.isDirectory(path)) throw new ObjFormatException(name, 0, "is a folder, not an MTL file");
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
     * Reads MTL text held in a string.
     *
     * @param name the text's name in messages and warnings
     * @param text the whole MTL text
     * @return the materials and warnings
     * @throws ObjFormatException if the text is malformed, too long or has no materials
     */
    public static MtlLibrary parse(String name, String text) throws ObjFormatException {
        return read(name, new StringReader(text));
    }

    /**
     * Reads MTL text; {@code name} names it in messages. The reader is not closed.
     *
     * @param name the text's name in messages and warnings
     * @param text the MTL text
     * @return the materials and warnings
     * @throws ObjFormatException if the text cannot be read, is malformed, too long or has no materials
     */
    public static MtlLibrary read(String name, Reader text) throws ObjFormatException {
        MtlReader reader = new MtlReader(name);
        new BoundedLines(text, reader.file, "MTL", MAX_LINE_LENGTH, MAX_CHARACTERS)
                .forEach(
                        name,
                        (line, number) -> {
                            reader.lineNumber = number;
                            reader.parseLine(line);
                        },
                        () -> reader.sawStatement);
        return reader.finish();
    }

    private void parseLine(String raw) throws ObjFormatException {
        int hash = raw.indexOf('#');
        String line = (hash >= 0 ? raw.substring(0, hash) : raw).strip();
        if (line.isEmpty()) return;
        String[] tokens = line.split("\\s+");
        String keyword = tokens[0];
        boolean known = STATEMENTS.contains(keyword) || SKIPPED.containsKey(keyword);
        if (!sawStatement && !known) {
            // Not quoted: the file may be any file of the machine rather than an MTL file.
            throw error("does not start like an MTL file: its first statement is not one (a line starts with a"
                    + " keyword such as newmtl, Kd or map_Kd)");
        }
        sawStatement = true;
        if (!keyword.equals("newmtl") && name == null && STATEMENTS.contains(keyword)) {
            throw error("'" + keyword + "' before any 'newmtl': a material's statements follow 'newmtl name'");
        }
        switch (keyword) {
            case "newmtl" -> newMaterial(line.substring(keyword.length()).strip());
            case "Kd" -> kd = color(tokens);
            case "Ks" -> ks = color(tokens);
            case "Ka" -> ka = color(tokens);
            case "Ke" -> ke = color(tokens);
            case "Ns" -> ns = number(tokens, 0, 10_000, "0 to 10000 (the Phong exponent)");
            case "Ni" -> ni = number(tokens, 1e-3, 1e3, "0.001 to 1000 (the index of refraction)");
            case "d" -> dissolve = number(tokens, 0, 1, "0 (clear) to 1 (opaque)");
            case "Tr" -> dissolve = 1 - number(tokens, 0, 1, "0 (opaque) to 1 (clear)");
            case "illum" -> illum = illumination(tokens);
            case "map_Kd" -> mapKd = textureMap(tokens);
            default -> skip(keyword);
        }
    }

    private void newMaterial(String materialName) throws ObjFormatException {
        if (materialName.isEmpty()) throw error("'newmtl' needs a material name");
        if (materialName.length() > ObjReader.MAX_NAME_LENGTH) {
            throw error("'newmtl' name of " + materialName.length() + " characters; a material name may have at most "
                    + ObjReader.MAX_NAME_LENGTH);
        }
        store();
        if (materials.size() >= MAX_MATERIALS && !materials.containsKey(materialName)) {
            throw error("more than " + MAX_MATERIALS + " materials, the most an MTL file may have here");
        }
        if (materials.containsKey(materialName)) {
            note("material \"" + abbreviate(materialName) + "\" is defined again at line " + lineNumber
                    + "; the later definition is used");
        }
        name = materialName;
        nameLine = lineNumber;
        kd = ks = ka = ke = null;
        ns = ni = dissolve = null;
        illum = null;
        mapKd = null;
    }

    private void store() {
        if (name != null) {
            materials.put(name, new MtlMaterial(name, file, nameLine, kd, ks, ka, ke, ns, ni, dissolve, illum, mapKd));
        }
    }

    /** {@code K r [g b]}: one value is grey; every value finite and at least 0. */
    private Double3 color(String[] tokens) throws ObjFormatException {
        String keyword = tokens[0];
        int n = tokens.length - 1;
        if (n >= 1 && (tokens[1].equals("spectral") || tokens[1].equals("xyz"))) {
            throw error("'" + keyword + " " + tokens[1] + "' is not supported: give r g b values (0 to 1)");
        }
        if (n != 1 && n != 3) {
            throw error("'" + keyword + "' needs r g b (or one value for grey), but has " + n + " value"
                    + (n == 1 ? "" : "s"));
        }
        double r = value(tokens[1], keyword), g = n == 3 ? value(tokens[2], keyword) : r;
        double b = n == 3 ? value(tokens[3], keyword) : r;
        if (r < 0 || g < 0 || b < 0) {
            throw error("'" + keyword + "' values must be 0 or more (1 is full), but one was negative");
        }
        return new Double3(r, g, b);
    }

    private double number(String[] tokens, double min, double max, String allowed) throws ObjFormatException {
        String keyword = tokens[0];
        if (tokens.length != 2) {
            throw error("'" + keyword + "' needs one value, but has " + (tokens.length - 1));
        }
        double value = value(tokens[1], keyword);
        if (value < min || value > max) {
            throw error(
                    "'" + keyword + "' value " + abbreviate(tokens[1]) + " is out of range: allowed are " + allowed);
        }
        return value;
    }

    private int illumination(String[] tokens) throws ObjFormatException {
        if (tokens.length != 2 || !tokens[1].matches("\\d{1,2}") || Integer.parseInt(tokens[1]) > 10) {
            throw error("'illum' needs one illumination model, an integer 0 to 10, but was '"
                    + abbreviate(String.join(" ", java.util.Arrays.copyOfRange(tokens, 1, tokens.length))) + "'");
        }
        int model = Integer.parseInt(tokens[1]);
        if (model == 10) note("illum 10 (shadows on invisible surfaces) is shaded as illum 2");
        return model;
    }

    /** {@code map_Kd [options] file}: -clamp is applied, the other options are skipped with a warning. */
    private MtlMaterial.TextureMap textureMap(String[] tokens) throws ObjFormatException {
        boolean clamp = false;
        int i = 1;
        while (i < tokens.length && tokens[i].startsWith("-") && MAP_OPTIONS.containsKey(tokens[i])) {
            String option = tokens[i++];
            int most = MAP_OPTIONS.get(option);
            if (option.equals("-clamp")) {
                if (i >= tokens.length || !(tokens[i].equals("on") || tokens[i].equals("off"))) {
                    throw error("'map_Kd -clamp' needs on or off");
                }
                clamp = tokens[i++].equals("on");
                continue;
            }
            note("texture option '" + option + "' is not supported (skipped)");
            int taken = 0;
            // -o, -s, -t take 1 to 3 numbers; the others a fixed count of values.
            while (taken < most && i < tokens.length - 1 && (most != 3 || isNumber(tokens[i]))) {
                i++;
                taken++;
            }
            if (taken == 0) throw error("'map_Kd " + option + "' needs a value");
        }
        if (i >= tokens.length) throw error("'map_Kd' needs an image file name");
        String image = String.join(" ", java.util.Arrays.copyOfRange(tokens, i, tokens.length));
        if (image.startsWith("-")) {
            throw error("'map_Kd' option '" + abbreviate(tokens[i]) + "' is not a texture option");
        }
        return new MtlMaterial.TextureMap(image, clamp, lineNumber);
    }

    private static boolean isNumber(String token) {
        try {
            Double.parseDouble(token);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private double value(String token, String keyword) throws ObjFormatException {
        return Tokens.finite(token, keyword, file, lineNumber);
    }

    private void skip(String keyword) throws ObjFormatException {
        if (!keyword.matches("[A-Za-z_][A-Za-z0-9_]*")) {
            throw error("'" + abbreviate(keyword) + "' is not an MTL statement (a line starts with a keyword such as"
                    + " newmtl, Kd or map_Kd)");
        }
        skipped.computeIfAbsent(keyword, k -> new int[] {0, lineNumber})[0]++;
    }

    /** Records a warning once, however often its cause occurs. */
    private void note(String what) {
        if (!notes.contains(what)) notes.add(what);
    }

    private MtlLibrary finish() throws ObjFormatException {
        store();
        if (materials.isEmpty()) {
            throw new ObjFormatException(file, 0, "has no materials ('newmtl' lines)");
        }
        List<String> warnings = new ArrayList<>();
        for (Map.Entry<String, int[]> e : skipped.entrySet()) {
            int count = e.getValue()[0];
            warnings.add(file + ": skipped " + count + " '" + e.getKey() + "' statement" + (count == 1 ? "" : "s")
                    + " (first at line " + e.getValue()[1] + "): "
                    + SKIPPED.getOrDefault(e.getKey(), "not supported"));
        }
        for (String note : notes) warnings.add(file + ": " + note);
        return new MtlLibrary(file, materials, warnings);
    }

    private ObjFormatException error(String reason) {
        return new ObjFormatException(file, lineNumber, reason);
    }
}
