package sceneio;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Prototype;
import geometries.Sphere;
import geometries.Triangle;
import geometries.Tube;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.function.Supplier;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import scene.Scene;
import sceneio.model.AmbientDocument;
import sceneio.model.AxisDocument;
import sceneio.model.Coefficient;
import sceneio.model.CylinderDocument;
import sceneio.model.DirectionalLightDocument;
import sceneio.model.GeometryDocument;
import sceneio.model.GroupDocument;
import sceneio.model.InstanceDocument;
import sceneio.model.LightDocument;
import sceneio.model.MaterialDocument;
import sceneio.model.MaterialRef;
import sceneio.model.MeshDocument;
import sceneio.model.PlaneDocument;
import sceneio.model.PointLightDocument;
import sceneio.model.PolygonDocument;
import sceneio.model.SceneDocument;
import sceneio.model.SphereDocument;
import sceneio.model.SpotLightDocument;
import sceneio.model.SurfaceDocument;
import sceneio.model.TextureDocument;
import sceneio.model.TriangleDocument;
import sceneio.model.TubeDocument;
import sceneio.model.Vec3;

/**
 * Turns a {@link SceneDocument} into core objects: checks what is required, applies the defaults, loads OBJ
 * meshes and lets the core constructors validate the values. Every problem becomes a {@link SceneFileException}
 * at the JSON path of the offending value ({@link DocumentValues}). The lights, materials and geometries are built
 * here; the camera and the render settings by {@link CameraReader}.
 */
final class SceneBuilder {
    private final String file;
    /** The document's values as core values, and its problems at their JSON paths. */
    private final DocumentValues values;
    /** Where referenced files may be: the scene's folder tree and what the user allowed. */
    private final FileConfinement confinement;
    /** The files read besides the scene file, relative to its folder, each once. */
    private final List<String> files = new ArrayList<>();
    /** Each image file of the scene decoded once. */
    private final TextureLoader textures;
    /** Reads the OBJ meshes with their MTL files and textures. */
    private final MeshLoader meshes;

    private final List<String> warnings = new ArrayList<>();
    /** The scene's prototypes by name, in file order, and the names an instance placed. */
    private final Map<String, Prototype> prototypes = new java.util.LinkedHashMap<>();

    private final java.util.Set<String> placed = new java.util.HashSet<>();
    private final Map<String, Material> materials = new HashMap<>();

    /**
     * @param file the scene file's name for messages
     * @param baseDir folder that relative OBJ paths start from
     * @param text supplies the document's text, only on error, to find line and column (null: paths only)
     * @param alsoAllowed folders besides {@code baseDir} that referenced files may resolve into
     */
    SceneBuilder(String file, Path baseDir, Supplier<String> text, List<Path> alsoAllowed) {
        this.file = file;
        this.values = new DocumentValues(file, text);
        this.confinement = new FileConfinement(baseDir, alsoAllowed);
        this.textures = new TextureLoader(confinement, files);
        this.meshes = new MeshLoader(file, confinement, textures, warnings, files, new MeshLoader.Context() {
            @Override
            public SceneFileException fail(JsonPath at, String problem, Throwable cause) {
                return values.fail(at, problem, cause);
            }

            @Override
            public Material material(JsonPath at, MaterialRef ref) throws SceneFileException {
                return SceneBuilder.this.material(at, ref);
            }

            @Override
            public Color color(JsonPath at, Vec3 value) throws SceneFileException {
                return values.color(at, value);
            }
        });
    }

    LoadedScene build(SceneDocument d, String defaultName) throws SceneFileException {
        JsonPath root = JsonPath.ROOT;
        if (d == null) throw values.fail(root, "the document is null: a scene file holds one JSON object");
        if (d.version() != null && d.version() != 1) {
            throw values.fail(root.field("version"), "unsupported format version " + d.version() + "; allowed: 1");
        }
        String name = d.name() != null ? d.name() : defaultName;
        Scene scene = values.core(root.field("name"), () -> new Scene(name));
        if (d.seed() != null) scene.setSeed(d.seed());
        if (d.background() != null) scene.setBackground(values.color(root.field("background"), d.background()));
        if (d.ambient() != null) scene.setAmbientLight(ambient(root.field("ambient"), d.ambient()));
        if (d.materials() != null) {
            for (Map.Entry<String, MaterialDocument> e : d.materials().entrySet()) {
                JsonPath at = root.field("materials").field(e.getKey());
                if (e.getKey().isBlank()) throw values.fail(at, "a material name must not be empty");
                materials.put(e.getKey(), material(at, e.getValue()));
            }
        }
        if (d.lights() != null) {
            for (int i = 0; i < d.lights().size(); i++) {
                scene.lights.add(light(root.field("lights").index(i), d.lights().get(i)));
            }
        }
        if (d.prototypes() != null) {
            for (Map.Entry<String, GeometryDocument> e : d.prototypes().entrySet()) {
                JsonPath at = root.field("prototypes").field(e.getKey());
                if (e.getKey().isBlank()) throw values.fail(at, "a prototype name must not be empty");
                Intersectable geometry = geometry(at, e.getValue());
                prototypes.put(e.getKey(), values.core(at, () -> new Prototype(e.getKey(), geometry)));
            }
        }
        if (d.geometries() != null) {
            Geometries all = group(root.field("geometries"), d.geometries());
            scene.setGeometries(all);
        }
        for (String prototype : prototypes.keySet()) {
            if (!placed.contains(prototype))
                warnings.add("prototype \"" + prototype + "\" is defined but never placed");
        }
        Camera camera = new CameraReader(values).camera(d, scene);
        return new LoadedScene(d, scene, camera, warnings, files);
    }

    // ------------------------------------------------------------------ lights and materials

    private AmbientLight ambient(JsonPath at, AmbientDocument a) throws SceneFileException {
        Color color = values.color(at.field("color"), values.required(at, "color", a.color()));
        Double3 kA = a.kA() == null ? Double3.ONE : coefficient(at.field("kA"), a.kA());
        return values.core(at.field("kA"), () -> new AmbientLight(color, kA));
    }

    private LightSource light(JsonPath at, LightDocument light) throws SceneFileException {
        if (light == null) throw values.fail(at, "null is not a light: give an object with a \"type\"");
        // Values are checked where they are used; this catches what the core rejects of their combination.
        return values.core(at, () -> lightSource(at, light));
    }

    private LightSource lightSource(JsonPath at, LightDocument light) throws SceneFileException {
        if (light instanceof DirectionalLightDocument d) {
            Color color = values.color(at.field("color"), values.required(at, "color", d.color()));
            Vector direction = values.vector(at.field("direction"), values.required(at, "direction", d.direction()));
            return new DirectionalLight(color, direction);
        }
        if (light instanceof SpotLightDocument s) {
            Color color = values.color(at.field("color"), values.required(at, "color", s.color()));
            Point position = values.point(at.field("position"), values.required(at, "position", s.position()));
            Vector direction = values.vector(at.field("direction"), values.required(at, "direction", s.direction()));
            SpotLight spot = new SpotLight(color, position, direction);
            if (s.narrowBeam() != null) values.core(at.field("narrowBeam"), () -> spot.setNarrowBeam(s.narrowBeam()));
            attenuation(at, spot, s.kC(), s.kL(), s.kQ(), s.radius(), s.samples(), s.range());
            return spot;
        }
        PointLightDocument p = (PointLightDocument) light;
        Color color = values.color(at.field("color"), values.required(at, "color", p.color()));
        Point position = values.point(at.field("position"), values.required(at, "position", p.position()));
        PointLight point = new PointLight(color, position);
        attenuation(at, point, p.kC(), p.kL(), p.kQ(), p.radius(), p.samples(), p.range());
        return point;
    }

    private void attenuation(
            JsonPath at, PointLight light, Double kC, Double kL, Double kQ, Double radius, Integer n, Double range)
            throws SceneFileException {
        if (range != null) values.core(at.field("range"), () -> light.setRange(range));
        if (kC != null) values.core(at.field("kC"), () -> light.setKc(kC));
        if (kL != null) values.core(at.field("kL"), () -> light.setKl(kL));
        if (kQ != null) values.core(at.field("kQ"), () -> light.setKq(kQ));
        if (radius != null) values.core(at.field("radius"), () -> light.setRadius(radius));
        if (n != null) values.core(at.field("samples"), () -> light.setNumSamples(n));
        if (!(light.getKc() > 0) && !(light.getKl() > 0) && !(light.getKq() > 0)) {
            throw values.fail(
                    at, "attenuation kC + kL d + kQ d^2 is zero: at least one of kC, kL, kQ must be positive");
        }
    }

    private Material material(JsonPath at, MaterialDocument m) throws SceneFileException {
        if (m == null) throw values.fail(at, "null is not a material: give an object such as {\"kD\": 0.5}");
        Material material = new Material();
        if (m.kA() != null) material.setKa(coefficient(at.field("kA"), m.kA()));
        if (m.kD() != null) material.setKd(coefficient(at.field("kD"), m.kD()));
        if (m.kS() != null) material.setKs(coefficient(at.field("kS"), m.kS()));
        if (m.shininess() != null) values.core(at.field("shininess"), () -> material.setShininess(m.shininess()));
        if (m.kR() != null) material.setKr(coefficient(at.field("kR"), m.kR()));
        if (m.kT() != null) material.setKt(coefficient(at.field("kT"), m.kT()));
        if (m.indexOfRefraction() != null) {
            values.core(at.field("indexOfRefraction"), () -> material.setIndexOfRefraction(m.indexOfRefraction()));
        }
        if (m.roughness() != null) values.core(at.field("roughness"), () -> material.setRoughness(m.roughness()));
        if (m.kDMap() != null) material.setKdMap(texture(at.field("kDMap"), m.kDMap()));
        return material;
    }

    private primitives.Texture texture(JsonPath at, TextureDocument t) throws SceneFileException {
        String name = values.required(at, "file", t.file());
        try {
            return textures.load(
                    name, meshes.displayName(name), t.wrap() == null ? primitives.Texture.Wrap.REPEAT : t.wrap());
        } catch (TextureLoader.TextureException e) {
            throw values.fail(at.field("file"), e.getMessage(), e);
        }
    }

    /** A coefficient, checked here because the core's range message would quote Double.MAX_VALUE. */
    private Double3 coefficient(JsonPath at, Coefficient c) throws SceneFileException {
        if (c.r() < 0 || c.g() < 0 || c.b() < 0) {
            String value = c.isUniform() ? String.valueOf(c.r()) : "[" + c.r() + ", " + c.g() + ", " + c.b() + "]";
            throw values.fail(at, "coefficients must be zero or positive (a number or [r, g, b]), but was " + value);
        }
        return new Double3(c.r(), c.g(), c.b());
    }

    // ------------------------------------------------------------------ geometries

    private Geometries group(JsonPath at, List<GeometryDocument> members) throws SceneFileException {
        Geometries group = new Geometries();
        for (int i = 0; i < members.size(); i++) group.add(geometry(at.index(i), members.get(i)));
        return group;
    }

    private Intersectable geometry(JsonPath at, GeometryDocument g) throws SceneFileException {
        if (g == null) throw values.fail(at, "null is not a geometry: give an object with a \"type\"");
        if (g instanceof MeshDocument mesh) return meshes.load(at, mesh);
        if (g instanceof GroupDocument group) {
            return group(at.field("geometries"), values.required(at, "geometries", group.geometries()));
        }
        if (g instanceof InstanceDocument instance) return instance(at, instance);
        Geometry geometry = values.core(at, () -> shape(at, g));
        SurfaceDocument surface = (SurfaceDocument) g;
        if (surface.emission() != null) geometry.setEmission(values.color(at.field("emission"), surface.emission()));
        if (surface.material() != null) geometry.setMaterial(material(at.field("material"), surface.material()));
        if (geometry.getMaterial().getKdMap() != null) {
            warnings.add(file + ": " + at + ": a "
                    + g.getClass().getSimpleName().replace("Document", "").toLowerCase(java.util.Locale.ROOT)
                    + " has no texture coordinates (only OBJ meshes with vt have them): its"
                    + " texture (kDMap) shows one colour");
        }
        return geometry;
    }

    private Instance instance(JsonPath at, InstanceDocument d) throws SceneFileException {
        String name = values.required(at, "of", d.of());
        Prototype prototype = prototypes.get(name);
        if (prototype == null) {
            throw values.fail(
                    at.field("of"),
                    "unknown prototype \"" + name + "\"; defined in \"prototypes\": "
                            + (prototypes.isEmpty() ? "none" : String.join(", ", new TreeSet<>(prototypes.keySet()))));
        }
        placed.add(name);
        Transform transform = InstanceTransforms.read(at, d, values::fail);
        return new Instance(prototype, transform);
    }

    private Material material(JsonPath at, MaterialRef ref) throws SceneFileException {
        if (ref.inline() != null) return material(at, ref.inline());
        Material named = materials.get(ref.name());
        if (named == null) {
            throw values.fail(
                    at,
                    "unknown material \"" + ref.name() + "\"; defined in \"materials\": "
                            + (materials.isEmpty() ? "none" : String.join(", ", new TreeSet<>(materials.keySet()))));
        }
        return named;
    }

    private Geometry shape(JsonPath at, GeometryDocument g) throws SceneFileException {
        if (g instanceof SphereDocument s) {
            Point center = values.point(at.field("center"), values.required(at, "center", s.center()));
            double radius = values.required(at, "radius", s.radius());
            return values.core(at.field("radius"), () -> new Sphere(center, radius));
        }
        if (g instanceof PlaneDocument p) {
            Point point = values.point(at.field("point"), values.required(at, "point", p.point()));
            Vector normal = values.vector(at.field("normal"), values.required(at, "normal", p.normal()));
            return new Plane(point, normal);
        }
        if (g instanceof TriangleDocument t) {
            Point[] v = values.points(at.field("vertices"), values.required(at, "vertices", t.vertices()));
            if (v.length != 3) {
                throw values.fail(
                        at.field("vertices"),
                        "a triangle needs exactly 3 vertices, but has " + v.length + " (use \"polygon\" for more)");
            }
            return values.core(at.field("vertices"), () -> new Triangle(v[0], v[1], v[2]));
        }
        if (g instanceof PolygonDocument p) {
            Point[] v = values.points(at.field("vertices"), values.required(at, "vertices", p.vertices()));
            return values.core(at.field("vertices"), () -> new Polygon(v));
        }
        if (g instanceof CylinderDocument c) {
            double radius = values.required(at, "radius", c.radius());
            Ray axis = axis(at.field("axis"), values.required(at, "axis", c.axis()));
            double height = values.required(at, "height", c.height());
            values.core(at.field("radius"), () -> new Tube(radius, axis));
            return values.core(at.field("height"), () -> new Cylinder(radius, axis, height));
        }
        if (g instanceof TubeDocument t) {
            double radius = values.required(at, "radius", t.radius());
            Ray axis = axis(at.field("axis"), values.required(at, "axis", t.axis()));
            return values.core(at.field("radius"), () -> new Tube(radius, axis));
        }
        throw new IllegalStateException("meshes are loaded by MeshLoader");
    }

    private Ray axis(JsonPath at, AxisDocument a) throws SceneFileException {
        Point origin = values.point(at.field("origin"), values.required(at, "origin", a.origin()));
        Vector direction = values.vector(at.field("direction"), values.required(at, "direction", a.direction()));
        return new Ray(origin, direction);
    }
}
