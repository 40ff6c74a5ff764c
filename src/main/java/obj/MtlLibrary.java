package obj;

import java.util.List;
import java.util.Map;

/**
 * The materials of an MTL file by name, in file order, and the warnings about what was skipped.
 *
 * @param file the file's name, for messages
 * @param materials the materials by {@code newmtl} name
 * @param warnings one line per kind of skipped statement
 */
public record MtlLibrary(String file, Map<String, MtlMaterial> materials, List<String> warnings) {
    /**
     * Copies the map and list into unmodifiable ones (the map keeps the file's order).
     *
     * @param file the file's name
     * @param materials the materials by name
     * @param warnings the warnings
     */
    public MtlLibrary {
        materials = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(materials));
        warnings = List.copyOf(warnings);
    }
}
