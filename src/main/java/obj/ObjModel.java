package obj;

import java.util.List;

/**
 * An OBJ file read with its materials: one {@link ObjMesh} per {@code usemtl} material (in order of first use;
 * faces before any {@code usemtl} have a null material), the {@code mtllib} files it names, and the warnings.
 * Each part has its own vertices (OBJ's shared ones copied into every part that uses them).
 *
 * @param parts the triangles of each material, at least one part, none empty
 * @param libraries the {@code mtllib} references in file order
 * @param warnings one line per kind of skipped statement or ignored data
 */
public record ObjModel(List<ObjMesh> parts, List<Library> libraries, List<String> warnings) {
    /**
     * Copies the lists into unmodifiable ones.
     *
     * @param parts the triangles of each material
     * @param libraries the {@code mtllib} references
     * @param warnings the warnings
     */
    public ObjModel {
        parts = List.copyOf(parts);
        libraries = List.copyOf(libraries);
        warnings = List.copyOf(warnings);
    }

    /**
     * A material library an OBJ file names ({@code mtllib name}), relative to the OBJ file's folder.
     *
     * @param name the file name as written
     * @param line the 1-based line of the {@code mtllib} statement, for messages
     */
    public record Library(String name, int line) {}
}
