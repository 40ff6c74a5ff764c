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
import primitives.Limits;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.ProgressiveSettings;
import renderer.RayTracerType;
import renderer.RenderMemory;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;
import sceneio.model.AmbientDocument;
import sceneio.model.AxisDocument;
import sceneio.model.CameraDocument;
import sceneio.model.Coefficient;
import sceneio.model.CylinderDocument;
import sceneio.model.DepthOfFieldDocument;
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
import sceneio.model.RenderDocument;
import sceneio.model.SamplingDocument;
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
 * at the JSON path of the offending value (with its line and column when the text is known); the core's
 * {@code IllegalArgumentException} messages say what is allowed, so they are kept and given a place.
 */
final class SceneBuilder {
    /** Largest image (pixels), as in the core's image writer: beyond it the pixel buffer cannot be allocated. */
    private static final long MAX_PIXELS = 1L << 28;

    private final String file;
    /** Where referenced files may be: the scene's folder tree and what the user allowed. */
    private final FileConfinement confinement;
    /** The files read besides the scene file, relative to its folder, each once. */
    private final List<String> files = new ArrayList<>();
    /** Each image file of the scene decoded once. */
    private final TextureLoader textures;
    /** Reads the OBJ meshes with their MTL files and textures. */
    private final MeshLoader meshes;

    private final Supplier<String> text;
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
        this.text = text;
        this.confinement = new FileConfinement(baseDir, alsoAllowed);
        this.textures = new TextureLoader(confinement, files);
        this.meshes = new MeshLoader(file, confinement, textures, warnings, files, new MeshLoader.Context() {
            @Override
            public SceneFileException fail(JsonPath at, String problem, Throwable cause) {
                return SceneBuilder.this.fail(at, problem, cause);
            }

            @Override
            public Material material(JsonPath at, MaterialRef ref) throws SceneFileException {
                return SceneBuilder.this.material(at, ref);
            }

            @Override
            public Color color(JsonPath at, Vec3 value) throws SceneFileException {
                return SceneBuilder.this.color(at, value);
            }
        });
    }

    LoadedScene build(SceneDocument d, String defaultName) throws SceneFileException {
        JsonPath root = JsonPath.ROOT;
        if (d == null) throw fail(root, "the document is null: a scene file holds one JSON object");
        if (d.version() != null && d.version() != 1) {
            throw fail(root.field("version"), "unsupported format version " + d.version() + "; allowed: 1");
        }
        String name = d.name() != null ? d.name() : defaultName;
        Scene scene = core(root.field("name"), () -> new Scene(name));
        if (d.seed() != null) scene.setSeed(d.seed());
        if (d.background() != null) scene.setBackground(color(root.field("background"), d.background()));
        if (d.ambient() != null) scene.setAmbientLight(ambient(root.field("ambient"), d.ambient()));
        if (d.materials() != null) {
            for (Map.Entry<String, MaterialDocument> e : d.materials().entrySet()) {
                JsonPath at = root.field("materials").field(e.getKey());
                if (e.getKey().isBlank()) throw fail(at, "a material name must not be empty");
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
                if (e.getKey().isBlank()) throw fail(at, "a prototype name must not be empty");
                Intersectable geometry = geometry(at, e.getValue());
                prototypes.put(e.getKey(), core(at, () -> new Prototype(e.getKey(), geometry)));
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
        Camera camera = camera(d, scene);
        return new LoadedScene(d, scene, camera, warnings, files);
    }

    // ------------------------------------------------------------------ camera and render settings

    private Camera camera(SceneDocument d, Scene scene) throws SceneFileException {
        JsonPath root = JsonPath.ROOT;
        CameraDocument c = d.camera();
        if (c == null) {
            throw fail(
                    root,
                    "the scene has no camera: add \"camera\": {\"location\": [x, y, z], \"lookAt\": [x, y, z],"
                            + " \"vpDistance\": d, \"vpWidth\": w, \"vpHeight\": h}");
        }
        RenderDocument r = d.render();
        if (r == null) {
            throw fail(root, "the scene has no render settings: add \"render\": {\"width\": w, \"height\": h}");
        }
        JsonPath at = root.field("camera");
        Camera.Builder b = Camera.getBuilder();
        Point location = point(at.field("location"), required(at, "location", c.location()));
        b.setLocation(location);
        if ((c.lookAt() == null) == (c.direction() == null)) {
            throw fail(at, "give exactly one of \"lookAt\" (a point to aim at) and \"direction\" (a vector)");
        }
        Vector to;
        if (c.lookAt() != null) {
            Point target = point(at.field("lookAt"), c.lookAt());
            if (target.equals(location)) {
                throw fail(at.field("lookAt"), "the camera cannot look at its own location " + location);
            }
            to = core(at.field("lookAt"), () -> target.subtract(location)); // may overflow for huge coordinates
        } else {
            to = vector(at.field("direction"), c.direction());
        }
        // Default up: +Z (the scenes' world is Z-up), or +Y when looking straight up or down.
        Vector up = c.up() != null
                ? vector(at.field("up"), c.up())
                : Math.abs(to.normalize().z) > 0.999999 ? Vector.AXIS_Y : Vector.AXIS_Z;
        core(at.field("up"), () -> b.setDirection(to, up));
        double distance = required(at, "vpDistance", c.vpDistance());
        double width = required(at, "vpWidth", c.vpWidth());
        double height = required(at, "vpHeight", c.vpHeight());
        core(at.field("vpDistance"), () -> b.setVpDistance(distance));
        // Width first with a stand-in height, so an error names the field that is wrong.
        core(at.field("vpWidth"), () -> b.setVpSize(width, 1));
        core(at.field("vpHeight"), () -> b.setVpSize(width, height));
        DepthOfFieldDocument dof = c.depthOfField();
        if (dof != null) {
            JsonPath dp = at.field("depthOfField");
            double focal = required(dp, "focalDistance", dof.focalDistance());
            double aperture = required(dp, "aperture", dof.aperture());
            core(dp, () -> b.setDepthOfField(focal, aperture));
            if (dof.samples() != null) {
                core(
                        dp.field("samples"),
                        () -> b.setApertureSampling(
                                new SamplingConfig(dof.samples(), TargetShape.CIRCLE, SamplingPattern.JITTERED)));
            }
        }

        JsonPath rp = root.field("render");
        int nX = required(rp, "width", r.width());
        int nY = required(rp, "height", r.height());
        if (nX < 1) throw fail(rp.field("width"), "width must be >= 1 pixel, but was " + nX);
        if (nY < 1) throw fail(rp.field("height"), "height must be >= 1 pixel, but was " + nY);
        if ((long) nX * nY > MAX_PIXELS) {
            throw fail(rp, "image of " + nX + " x " + nY + " pixels is too large (at most 2^28 pixels)");
        }
        b.setResolution(nX, nY);
        if (r.antiAliasing() != null) b.setSamplingConfig(sampling(rp.field("antiAliasing"), r.antiAliasing()));
        if (r.threads() != null) {
            int threads = r.threads();
            if (threads < 1 || threads > Limits.maxThreads()) {
                throw fail(rp.field("threads"), "threads must be in " + Limits.threadRange() + ", but was " + threads);
            }
            b.setThreads(threads);
        }
        RenderSettings settings = RenderSettings.DEFAULT;
        if (r.bvh() != null) settings = settings.withBvh(r.bvh());
        if (r.maxLevel() != null) {
            RenderSettings s = settings;
            settings = core(rp.field("maxLevel"), () -> s.withRecursion(r.maxLevel(), s.minAttenuation()));
        }
        if (r.shadowPattern() != null || r.adaptiveShadows() != null) {
            settings = settings.withShadowSampling(
                    r.shadowPattern() != null ? r.shadowPattern() : settings.shadowPattern(),
                    r.adaptiveShadows() != null ? r.adaptiveShadows() : settings.adaptiveShadows());
        }
        if (r.glossySamples() != null) {
            SamplingConfig glossy = core(
                    rp.field("glossySamples"),
                    () -> new SamplingConfig(
                            r.glossySamples(),
                            TargetShape.CIRCLE,
                            RenderSettings.DEFAULT.glossySampling().getPattern()));
            settings = settings.withGlossySampling(glossy);
        }
        if (r.lightCutoff() != null) {
            RenderSettings s = settings;
            settings = core(rp.field("lightCutoff"), () -> s.withLightCutoff(r.lightCutoff()));
        }
        b.setRenderSettings(settings);
        b.setProgressive(progressive(rp, r));
        b.setRayTracer(scene, RayTracerType.SIMPLE);
        Camera camera = core(at, b::build);
        // Memory last: it depends on the image, the samples, the threads and the geometry together.
        core(rp, () -> {
            RenderMemory.check(camera, nX, nY);
            return camera;
        });
        return camera;
    }

    private SamplingConfig sampling(JsonPath at, SamplingDocument s) throws SceneFileException {
        int samples = required(at, "samples", s.samples());
        TargetShape shape = s.shape() != null ? s.shape() : TargetShape.RECTANGLE;
        SamplingPattern pattern = s.pattern() != null ? s.pattern() : SamplingPattern.JITTERED;
        SamplingConfig config = core(at.field("samples"), () -> new SamplingConfig(samples, shape, pattern));
        if (s.adaptiveThreshold() != null) {
            config = core(
                    at.field("adaptiveThreshold"),
                    () -> new SamplingConfig(samples, shape, pattern).adaptive(s.adaptiveThreshold()));
        }
        return config;
    }

    // ------------------------------------------------------------------ lights and materials

    private AmbientLight ambient(JsonPath at, AmbientDocument a) throws SceneFileException {
        Color color = color(at.field("color"), required(at, "color", a.color()));
        Double3 kA = a.kA() == null ? Double3.ONE : coefficient(at.field("kA"), a.kA());
        return core(at.field("kA"), () -> new AmbientLight(color, kA));
    }

    private LightSource light(JsonPath at, LightDocument light) throws SceneFileException {
        if (light == null) throw fail(at, "null is not a light: give an object with a \"type\"");
        // Values are checked where they are used; this catches what the core rejects of their combination.
        return core(at, () -> lightSource(at, light));
    }

    private LightSource lightSource(JsonPath at, LightDocument light) throws SceneFileException {
        if (light instanceof DirectionalLightDocument d) {
            Color color = color(at.field("color"), required(at, "color", d.color()));
            Vector direction = vector(at.field("direction"), required(at, "direction", d.direction()));
            return new DirectionalLight(color, direction);
        }
        if (light instanceof SpotLightDocument s) {
            Color color = color(at.field("color"), required(at, "color", s.color()));
            Point position = point(at.field("position"), required(at, "position", s.position()));
            Vector direction = vector(at.field("direction"), required(at, "direction", s.direction()));
            SpotLight spot = new SpotLight(color, position, direction);
            if (s.narrowBeam() != null) core(at.field("narrowBeam"), () -> spot.setNarrowBeam(s.narrowBeam()));
            attenuation(at, spot, s.kC(), s.kL(), s.kQ(), s.radius(), s.samples(), s.range());
            return spot;
        }
        PointLightDocument p = (PointLightDocument) light;
        Color color = color(at.field("color"), required(at, "color", p.color()));
        Point position = point(at.field("position"), required(at, "position", p.position()));
        PointLight point = new PointLight(color, position);
        attenuation(at, point, p.kC(), p.kL(), p.kQ(), p.radius(), p.samples(), p.range());
        return point;
    }

    private void attenuation(
            JsonPath at, PointLight light, Double kC, Double kL, Double kQ, Double radius, Integer n, Double range)
            throws SceneFileException {
        if (range != null) core(at.field("range"), () -> light.setRange(range));
        if (kC != null) core(at.field("kC"), () -> light.setKc(kC));
        if (kL != null) core(at.field("kL"), () -> light.setKl(kL));
        if (kQ != null) core(at.field("kQ"), () -> light.setKq(kQ));
        if (radius != null) core(at.field("radius"), () -> light.setRadius(radius));
        if (n != null) core(at.field("samples"), () -> light.setNumSamples(n));
        if (!(light.getKc() > 0) && !(light.getKl() > 0) && !(light.getKq() > 0)) {
            throw fail(at, "attenuation kC + kL d + kQ d^2 is zero: at least one of kC, kL, kQ must be positive");
        }
    }

    private Material material(JsonPath at, MaterialDocument m) throws SceneFileException {
        if (m == null) throw fail(at, "null is not a material: give an object such as {\"kD\": 0.5}");
        Material material = new Material();
        if (m.kA() != null) material.setKa(coefficient(at.field("kA"), m.kA()));
        if (m.kD() != null) material.setKd(coefficient(at.field("kD"), m.kD()));
        if (m.kS() != null) material.setKs(coefficient(at.field("kS"), m.kS()));
        if (m.shininess() != null) core(at.field("shininess"), () -> material.setShininess(m.shininess()));
        if (m.kR() != null) material.setKr(coefficient(at.field("kR"), m.kR()));
        if (m.kT() != null) material.setKt(coefficient(at.field("kT"), m.kT()));
        if (m.indexOfRefraction() != null) {
            core(at.field("indexOfRefraction"), () -> material.setIndexOfRefraction(m.indexOfRefraction()));
        }
        if (m.roughness() != null) core(at.field("roughness"), () -> material.setRoughness(m.roughness()));
        if (m.kDMap() != null) material.setKdMap(texture(at.field("kDMap"), m.kDMap()));
        return material;
    }

    private primitives.Texture texture(JsonPath at, TextureDocument t) throws SceneFileException {
        String name = required(at, "file", t.file());
        try {
            return textures.load(
                    name, meshes.displayName(name), t.wrap() == null ? primitives.Texture.Wrap.REPEAT : t.wrap());
        } catch (TextureLoader.TextureException e) {
            throw fail(at.field("file"), e.getMessage(), e);
        }
    }

    /** A coefficient, checked here because the core's range message would quote Double.MAX_VALUE. */
    private Double3 coefficient(JsonPath at, Coefficient c) throws SceneFileException {
        if (c.r() < 0 || c.g() < 0 || c.b() < 0) {
            String value = c.isUniform() ? String.valueOf(c.r()) : "[" + c.r() + ", " + c.g() + ", " + c.b() + "]";
            throw fail(at, "coefficients must be zero or positive (a number or [r, g, b]), but was " + value);
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
        if (g == null) throw fail(at, "null is not a geometry: give an object with a \"type\"");
        if (g instanceof MeshDocument mesh) return meshes.load(at, mesh);
        if (g instanceof GroupDocument group) {
            return group(at.field("geometries"), required(at, "geometries", group.geometries()));
        }
        if (g instanceof InstanceDocument instance) return instance(at, instance);
        Geometry geometry = core(at, () -> shape(at, g));
        SurfaceDocument surface = (SurfaceDocument) g;
        if (surface.emission() != null) geometry.setEmission(color(at.field("emission"), surface.emission()));
        if (surface.material() != null) geometry.setMaterial(material(at.field("material"), surface.material()));
        if (geometry.getMaterial().getKdMap() != null) {
            warnings.add(file + ": " + at + ": a "
                    + g.getClass().getSimpleName().replace("Document", "").toLowerCase(java.util.Locale.ROOT)
                    + " has no texture coordinates (only OBJ meshes with vt have them): its"
                    + " texture (kDMap) shows one colour");
        }
        return geometry;
    }

    /** Progressive sampling from {@code targetError} or {@code timeBudget}, or null for fixed sampling. */
    private ProgressiveSettings progressive(JsonPath rp, RenderDocument r) throws SceneFileException {
        if (r.targetError() != null && r.timeBudget() != null) {
            throw fail(rp.field("timeBudget"), "give either \"targetError\" or \"timeBudget\", not both");
        }
        if (r.targetError() != null) {
            return core(rp.field("targetError"), () -> ProgressiveSettings.targetError(r.targetError()));
        }
        if (r.timeBudget() != null) {
            return core(rp.field("timeBudget"), () -> ProgressiveSettings.timeBudget(r.timeBudget()));
        }
        return null;
    }

    private Instance instance(JsonPath at, InstanceDocument d) throws SceneFileException {
        String name = required(at, "of", d.of());
        Prototype prototype = prototypes.get(name);
        if (prototype == null) {
            throw fail(
                    at.field("of"),
                    "unknown prototype \"" + name + "\"; defined in \"prototypes\": "
                            + (prototypes.isEmpty() ? "none" : String.join(", ", new TreeSet<>(prototypes.keySet()))));
        }
        placed.add(name);
        Transform transform = InstanceTransforms.read(at, d, this::fail);
        return new Instance(prototype, transform);
    }

    private Material material(JsonPath at, MaterialRef ref) throws SceneFileException {
        if (ref.inline() != null) return material(at, ref.inline());
        Material named = materials.get(ref.name());
        if (named == null) {
            throw fail(
                    at,
                    "unknown material \"" + ref.name() + "\"; defined in \"materials\": "
                            + (materials.isEmpty() ? "none" : String.join(", ", new TreeSet<>(materials.keySet()))));
        }
        return named;
    }

    private Geometry shape(JsonPath at, GeometryDocument g) throws SceneFileException {
        if (g instanceof SphereDocument s) {
            Point center = point(at.field("center"), required(at, "center", s.center()));
            double radius = required(at, "radius", s.radius());
            return core(at.field("radius"), () -> new Sphere(center, radius));
        }
        if (g instanceof PlaneDocument p) {
            Point point = point(at.field("point"), required(at, "point", p.point()));
            Vector normal = vector(at.field("normal"), required(at, "normal", p.normal()));
            return new Plane(point, normal);
        }
        if (g instanceof TriangleDocument t) {
            Point[] v = points(at.field("vertices"), required(at, "vertices", t.vertices()));
            if (v.length != 3) {
                throw fail(
                        at.field("vertices"),
                        "a triangle needs exactly 3 vertices, but has " + v.length + " (use \"polygon\" for more)");
            }
            return core(at.field("vertices"), () -> new Triangle(v[0], v[1], v[2]));
        }
        if (g instanceof PolygonDocument p) {
            Point[] v = points(at.field("vertices"), required(at, "vertices", p.vertices()));
            return core(at.field("vertices"), () -> new Polygon(v));
        }
        if (g instanceof CylinderDocument c) {
            double radius = required(at, "radius", c.radius());
            Ray axis = axis(at.field("axis"), required(at, "axis", c.axis()));
            double height = required(at, "height", c.height());
            core(at.field("radius"), () -> new Tube(radius, axis));
            return core(at.field("height"), () -> new Cylinder(radius, axis, height));
        }
        if (g instanceof TubeDocument t) {
            double radius = required(at, "radius", t.radius());
            Ray axis = axis(at.field("axis"), required(at, "axis", t.axis()));
            return core(at.field("radius"), () -> new Tube(radius, axis));
        }
        throw new IllegalStateException("meshes are loaded by MeshLoader");
    }

    private Ray axis(JsonPath at, AxisDocument a) throws SceneFileException {
        Point origin = point(at.field("origin"), required(at, "origin", a.origin()));
        Vector direction = vector(at.field("direction"), required(at, "direction", a.direction()));
        return new Ray(origin, direction);
    }

    // ------------------------------------------------------------------ values

    private Point[] points(JsonPath at, List<Vec3> vertices) throws SceneFileException {
        Point[] points = new Point[vertices.size()];
        for (int i = 0; i < points.length; i++) {
            points[i] = point(at.index(i), required(at.index(i), vertices.get(i)));
        }
        return points;
    }

    private Point point(JsonPath at, Vec3 v) throws SceneFileException {
        return core(at, () -> new Point(v.x(), v.y(), v.z()));
    }

    private Vector vector(JsonPath at, Vec3 v) throws SceneFileException {
        return core(at, () -> new Vector(v.x(), v.y(), v.z()));
    }

    private Color color(JsonPath at, Vec3 v) throws SceneFileException {
        if (v.x() < 0 || v.y() < 0 || v.z() < 0) {
            throw fail(
                    at,
                    "colour channels must be >= 0 (0..255 is the usual range), but were [" + v.x() + ", " + v.y() + ", "
                            + v.z() + "]");
        }
        return new Color(v.x(), v.y(), v.z());
    }

    private <T> T required(JsonPath parent, String field, T value) throws SceneFileException {
        if (value == null) throw fail(parent, "missing required field \"" + field + "\"");
        return value;
    }

    private <T> T required(JsonPath at, T value) throws SceneFileException {
        if (value == null) throw fail(at, "null is not allowed here");
        return value;
    }

    /** A core construction whose IllegalArgument/IllegalState message is reported at {@code at}. */
    private <T> T core(JsonPath at, CoreCall<T> call) throws SceneFileException {
        try {
            return call.get();
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw fail(at, e.getMessage() == null ? e.toString() : e.getMessage(), e);
        }
    }

    /** A constructor or setter of the core (or a step of the builder that calls some). */
    @FunctionalInterface
    private interface CoreCall<T> {
        T get() throws SceneFileException;
    }

    private SceneFileException fail(JsonPath at, String problem) {
        return fail(at, problem, null);
    }

    private SceneFileException fail(JsonPath at, String problem, Throwable cause) {
        String source = text == null ? null : text.get();
        int[] place = source == null ? null : JsonLocator.locateNearest(source, at);
        return new SceneFileException(
                file, place == null ? 0 : place[0], place == null ? 0 : place[1], at.toString(), problem, cause);
    }
}
