package sceneio;

import geometries.Geometries;
import geometries.Intersectable;
import geometries.Mesh;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import obj.MtlLibrary;
import obj.MtlMaterial;
import obj.MtlReader;
import obj.ObjFormatException;
import obj.ObjMesh;
import obj.ObjModel;
import obj.ObjReader;
import primitives.Color;
import primitives.Material;
import primitives.Printable;
import primitives.Texture;
import sceneio.model.MaterialRef;
import sceneio.model.MeshDocument;
import sceneio.model.Vec3;

/**
 * Loads the {@code mesh} geometries of a scene: the OBJ file, the MTL files it names and their textures, all
 * through the scene's {@link FileConfinement} and size limits; each MTL file and image is read once per scene.
 * An OBJ with several materials becomes one {@link Mesh} per material in a {@link Geometries}; a mesh document's
 * {@code material} overrides them all and its {@code materials} single ones by name.
 */
final class MeshLoader {
    /** How the scene builder reports a problem at a JSON path and resolves a material reference. */
    interface Context {
        SceneFileException fail(JsonPath at, String problem, Throwable cause);

        Material material(JsonPath at, MaterialRef ref) throws SceneFileException;

        Color color(JsonPath at, Vec3 value) throws SceneFileException;
    }

    private final String sceneFile;
    private final FileConfinement confinement;
    private final TextureLoader textures;
    private final List<String> warnings;
    /** Receives the reference of each OBJ and MTL file read (once each). */
    private final List<String> files;

    private final Context context;
    /** MTL files read, by real path. */
    private final Map<Path, MtlLibrary> libraries = new HashMap<>();
    /** The material made of each MTL material (MTL files are read once, so identity is the material). */
    private final Map<MtlMaterial, Material> mtlMaterials = new IdentityHashMap<>();
    /** The reference (relative to the scene folder) of each MTL material's file, for its texture's path. */
    private final Map<MtlMaterial, String> references = new IdentityHashMap<>();

    MeshLoader(
            String sceneFile,
            FileConfinement confinement,
            TextureLoader textures,
            List<String> warnings,
            List<String> files,
            Context context) {
        this.sceneFile = sceneFile;
        this.confinement = confinement;
        this.textures = textures;
        this.warnings = warnings;
        this.files = files;
        this.context = context;
    }

    Intersectable load(JsonPath at, MeshDocument m) throws SceneFileException {
        JsonPath fileAt = at.field("file");
        if (m.file() == null) throw context.fail(at, "missing required field \"file\"", null);
        String name = m.file();
        Path path;
        try {
            // Resolved inside the allowed folders before anything is looked at (FileConfinement).
            path = confinement.resolve("OBJ file", name);
        } catch (IllegalArgumentException e) {
            throw context.fail(fileAt, e.getMessage(), e);
        }
        if (!Files.exists(path, LinkOption.NOFOLLOW_LINKS)) {
            throw context.fail(
                    fileAt, "OBJ file \"" + Printable.of(name) + "\" not found (looked for " + path + ")", null);
        }
        String objName = displayName(name);
        ObjModel model;
        try {
            model = ObjReader.readModel(path, objName);
        } catch (ObjFormatException e) {
            throw context.fail(fileAt, "OBJ file " + e.getMessage(), e);
        }
        warnings.addAll(model.warnings());
        if (!files.contains(name)) files.add(name);
        double scale = m.scale() == null ? 1 : m.scale();
        if (!(scale > 0)) throw context.fail(at.field("scale"), "scale must be positive, but was " + scale, null);
        Vec3 t = m.translate() == null ? new Vec3(0, 0, 0) : m.translate();
        boolean smooth = m.smooth() == null || m.smooth();

        Material all = m.material() == null ? null : context.material(at.field("material"), m.material());
        Color emission = m.emission() == null ? null : context.color(at.field("emission"), m.emission());
        Map<String, Material> overrides = overrides(at, m, model);
        // The MTL files are needed only for materials that nothing in the scene file overrides.
        Map<String, MtlMaterial> mtl = null;
        List<Mesh> meshes = new ArrayList<>();
        for (ObjMesh part : model.parts()) {
            Material material = all;
            Color glow = emission;
            String partName = part.material();
            if (material == null && partName != null) {
                material = overrides.get(partName);
                if (material == null) {
                    if (mtl == null) mtl = libraries(fileAt, name, objName, model);
                    MtlMaterial found = mtl.get(partName);
                    if (found == null) {
                        throw context.fail(
                                fileAt,
                                "OBJ file " + objName + " uses material \"" + Printable.of(partName) + "\" (usemtl),"
                                        + " which "
                                        + (model.libraries().isEmpty()
                                                ? "no material library defines: the file has no mtllib"
                                                : "none of its material libraries defines; they define: "
                                                        + names(mtl.keySet()))
                                        + "; define it there or give it in the mesh's \"materials\"",
                                null);
                    }
                    material = material(fileAt, found);
                    if (glow == null) glow = found.emission();
                }
            }
            Material chosen = material;
            Color chosenGlow = glow;
            if (chosen != null && chosen.getKdMap() != null && part.texCoords() == null) {
                warnings.add(objName + ": the faces of "
                        + (partName == null ? "no material" : "material \"" + Printable.of(partName) + "\"")
                        + " have a textured material (kDMap, map_Kd) but no texture"
                        + " coordinates (vt): the texture shows one colour");
            }
            double[] v = part.vertices().clone();
            for (int i = 0; i < v.length; i += 3) {
                v[i] = v[i] * scale + t.x();
                v[i + 1] = v[i + 1] * scale + t.y();
                v[i + 2] = v[i + 2] * scale + t.z();
            }
            try {
                Mesh mesh = new Mesh(v, part.indices(), smooth ? part.normals() : null, part.texCoords());
                if (chosen != null) mesh.setMaterial(chosen);
                if (chosenGlow != null) mesh.setEmission(chosenGlow);
                meshes.add(mesh);
            } catch (IllegalArgumentException e) {
                throw context.fail(at, e.getMessage(), e);
            }
        }
        if (meshes.size() == 1) return meshes.get(0);
        Geometries group = new Geometries();
        for (Mesh mesh : meshes) group.add(mesh);
        return group;
    }

    /** The mesh document's {@code materials}, each naming a material the OBJ file uses. */
    private Map<String, Material> overrides(JsonPath at, MeshDocument m, ObjModel model) throws SceneFileException {
        Map<String, Material> overrides = new HashMap<>();
        if (m.materials() == null) return overrides;
        TreeSet<String> used = new TreeSet<>();
        for (ObjMesh part : model.parts()) {
            if (part.material() != null) used.add(part.material());
        }
        for (Map.Entry<String, MaterialRef> e : m.materials().entrySet()) {
            JsonPath entry = at.field("materials").field(e.getKey());
            if (!used.contains(e.getKey())) {
                throw context.fail(
                        entry,
                        "the OBJ file uses no material \"" + Printable.of(e.getKey()) + "\"; its materials (usemtl)"
                                + " are: " + (used.isEmpty() ? "none" : names(used)),
                        null);
            }
            if (e.getValue() == null) throw context.fail(entry, "null is not a material", null);
            overrides.put(e.getKey(), context.material(entry, e.getValue()));
        }
        return overrides;
    }

    /** The materials of the OBJ file's libraries by name (the first library defining a name wins). */
    private Map<String, MtlMaterial> libraries(JsonPath fileAt, String objReference, String objName, ObjModel model)
            throws SceneFileException {
        Map<String, MtlMaterial> all = new LinkedHashMap<>();
        for (ObjModel.Library library : model.libraries()) {
            String where = "OBJ file " + objName + ":" + library.line() + ": mtllib: ";
            String reference = sibling(objReference, library.name());
            Path path;
            try {
                path = confinement.resolve("MTL file", reference);
            } catch (IllegalArgumentException e) {
                throw context.fail(fileAt, where + e.getMessage(), e);
            }
            MtlLibrary read = libraries.get(path);
            if (read == null) {
                if (!Files.exists(path, LinkOption.NOFOLLOW_LINKS)) {
                    throw context.fail(
                            fileAt,
                            where + "MTL file \"" + Printable.of(library.name()) + "\" not found (looked for " + path
                                    + ")",
                            null);
                }
                try {
                    read = MtlReader.read(path, displayName(reference));
                } catch (ObjFormatException e) {
                    throw context.fail(fileAt, where + "MTL file " + e.getMessage(), e);
                }
                libraries.put(path, read);
                files.add(reference);
                warnings.addAll(read.warnings());
                for (MtlMaterial material : read.materials().values()) references.put(material, reference);
            }
            for (Map.Entry<String, MtlMaterial> e : read.materials().entrySet())
                all.putIfAbsent(e.getKey(), e.getValue());
        }
        return all;
    }

    /** The library material of an MTL material, with its texture; made once per MTL material. */
    private Material material(JsonPath fileAt, MtlMaterial mtl) throws SceneFileException {
        Material material = mtlMaterials.get(mtl);
        if (material != null) return material;
        String where = "MTL file " + mtl.file() + ":" + mtl.line() + ": material \"" + Printable.of(mtl.name()) + "\"";
        try {
            material = mtl.toMaterial();
        } catch (IllegalArgumentException e) {
            throw context.fail(fileAt, where + ": " + e.getMessage(), e);
        }
        MtlMaterial.TextureMap map = mtl.mapKd();
        if (map != null) {
            // The image is relative to the MTL file, which is relative to the OBJ file.
            String reference = sibling(references.get(mtl), map.file());
            try {
                material.setKdMap(textures.load(
                        reference, displayName(reference), map.clamp() ? Texture.Wrap.CLAMP : Texture.Wrap.REPEAT));
            } catch (TextureLoader.TextureException e) {
                throw context.fail(
                        fileAt, "MTL file " + mtl.file() + ":" + map.line() + ": map_Kd: " + e.getMessage(), e);
            }
        }
        mtlMaterials.put(mtl, material);
        return material;
    }

    /** A file named in {@code reference}'s file, relative to the same scene folder: beside {@code reference}. */
    static String sibling(String reference, String name) {
        // An absolute name stays absolute, so the confinement refuses it as such.
        if (name.startsWith("/") || name.startsWith("\\")) return name;
        int slash = Math.max(reference.lastIndexOf('/'), reference.lastIndexOf('\\'));
        return slash < 0 ? name : reference.substring(0, slash + 1) + name;
    }

    private static String names(java.util.Collection<String> names) {
        List<String> quoted = new ArrayList<>();
        for (String n : new TreeSet<>(names)) quoted.add("\"" + Printable.of(n) + "\"");
        return String.join(", ", quoted);
    }

    /** A referenced path as the user sees it: beside the scene file's name (e.g. scenes/models/cube.obj). */
    String displayName(String reference) {
        try {
            return Path.of(sceneFile).resolveSibling(reference).normalize().toString();
        } catch (InvalidPathException e) {
            return reference;
        }
    }
}
