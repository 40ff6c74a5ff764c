package sceneio;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
import geometries.Intersectable;
import geometries.Mesh;
import geometries.Plane;
import geometries.Polygon;
import geometries.Prototype;
import geometries.Sphere;
import geometries.Triangle;
import geometries.Tube;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import obj.ObjWriter;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import renderer.Camera;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
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
import sceneio.model.TriangleDocument;
import sceneio.model.TubeDocument;
import sceneio.model.Vec3;

/**
 * Turns a scene built in Java, with its camera, into a scene file: the JSON document plus one OBJ file per mesh
 * in a {@code models} folder beside it. Materials shared by several geometries become named materials. What the
 * format cannot say is an error naming it (a user-written {@link Intersectable} or light type).
 */
public final class SceneExporter {
    private final Path folder;
    private final String prefix;
    private final Map<Material, String> materialNames = new IdentityHashMap<>();
    private final Map<String, MaterialDocument> materials = new LinkedHashMap<>();
    private final Map<Material, Integer> uses = new IdentityHashMap<>();
    private final Map<Prototype, String> prototypeNames = new IdentityHashMap<>();
    private final Map<String, GeometryDocument> prototypes = new LinkedHashMap<>();
    private final java.util.Set<Prototype> counted = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
    private int meshes;

    private SceneExporter(Path jsonFile) {
        this.folder = jsonFile.toAbsolutePath().getParent();
        String name = jsonFile.getFileName().toString();
        this.prefix = name.endsWith(".json") ? name.substring(0, name.length() - 5) : name;
    }

    /**
     * Writes {@code scene} seen by {@code camera} to {@code jsonFile} and its meshes to {@code models/<name>/mesh-N.obj}.
     *
     * @param scene the scene to write; its geometries and lights must be of the library's types
     * @param camera the camera whose position, view plane, depth of field and render settings are written
     * @param jsonFile the scene file to write; the meshes go to a {@code models} folder beside it
     * @return the document written to {@code jsonFile}
     * @throws IllegalArgumentException if a geometry or light cannot be written in the scene format
     */
    public static SceneDocument export(Scene scene, Camera camera, Path jsonFile) {
        SceneExporter exporter = new SceneExporter(jsonFile);
        SceneDocument document = exporter.document(scene, camera);
        SceneWriter.write(document, jsonFile);
        return document;
    }

    private SceneDocument document(Scene scene, Camera camera) {
        countUses(scene.geometries);
        List<GeometryDocument> geometries = new ArrayList<>();
        for (Intersectable g : scene.geometries.getMembers()) geometries.add(geometry(g));
        List<LightDocument> lights = new ArrayList<>();
        for (LightSource light : scene.lights) lights.add(light(light));
        return new SceneDocument(
                1,
                scene.getName(),
                scene.getSeed(),
                vec(scene.background),
                new AmbientDocument(vec(scene.ambientLight.getIntensity()), null),
                camera(camera),
                render(camera),
                materials.isEmpty() ? null : materials,
                prototypes.isEmpty() ? null : prototypes,
                lights,
                geometries);
    }

    /**
     * The name of a prototype in the file, written to {@code prototypes} the first time an instance places it (its
     * own name, suffixed when two prototypes share one).
     */
    private String prototypeName(Prototype prototype) {
        String known = prototypeNames.get(prototype);
        if (known != null) return known;
        String name = prototype.name();
        for (int k = 2; prototypes.containsKey(name); k++) name = prototype.name() + "-" + k;
        prototypeNames.put(prototype, name);
        prototypes.put(name, null); // reserve the name (and the order) before the members are written
        prototypes.put(name, geometry(prototype.geometry()));
        return name;
    }

    private void countUses(Intersectable g) {
        if (g instanceof Geometries group) {
            for (Intersectable member : group.getMembers()) countUses(member);
        } else if (g instanceof Instance instance) {
            if (counted.add(instance.prototype()))
                countUses(instance.prototype().geometry());
        } else if (g instanceof Geometry geometry) {
            uses.merge(geometry.getMaterial(), 1, Integer::sum);
        }
    }

    private GeometryDocument geometry(Intersectable g) {
        if (g instanceof Geometries group) {
            List<GeometryDocument> members = new ArrayList<>();
            for (Intersectable member : group.getMembers()) members.add(geometry(member));
            return new GroupDocument(members);
        }
        if (g instanceof Instance instance)
            return InstanceTransforms.write(prototypeName(instance.prototype()), instance.transform());
        if (!(g instanceof Geometry geometry)) {
            throw new IllegalArgumentException("a " + g.getClass().getName()
                    + " cannot be written to a scene file: only the library's geometries can");
        }
        MaterialRef material = material(geometry.getMaterial());
        Vec3 emission = geometry.getEmission().isBlack() ? null : vec(geometry.getEmission());
        if (g instanceof Sphere s) {
            return new SphereDocument(vec(s.getCenter()), s.getRadius(), material, emission);
        }
        if (g instanceof Plane p) return new PlaneDocument(vec(p.getPoint()), vec(p.getNormal()), material, emission);
        if (g instanceof Triangle t) return new TriangleDocument(vertices(t), material, emission);
        if (g instanceof Polygon p) return new PolygonDocument(vertices(p), material, emission);
        if (g instanceof Cylinder c) {
            return new CylinderDocument(c.getRadius(), axis(c.getAxis()), c.getHeight(), material, emission);
        }
        if (g instanceof Tube t) return new TubeDocument(t.getRadius(), axis(t.getAxis()), material, emission);
        if (g instanceof Mesh m) {
            String file = "models/" + prefix + "/mesh-" + meshes++ + ".obj";
            ObjWriter.write(
                    m, folder.resolve(file), "mesh of scene " + prefix + " (" + m.triangleCount() + " triangles)");
            return new MeshDocument(file, null, null, m.getNormals() != null ? null : false, material, emission);
        }
        throw new IllegalArgumentException("a " + g.getClass().getName() + " cannot be written to a scene file");
    }

    /** A material used more than once becomes a named one; a material used once is written in place. */
    private MaterialRef material(Material m) {
        if (m.getKdMap() != null) {
            // The texels are in memory only: there is no image file to refer to.
            throw new IllegalArgumentException("a material with a kD map (texture) cannot be written to a scene file:"
                    + " reference the image from the scene file or an MTL file instead");
        }
        MaterialDocument d = new MaterialDocument(
                coefficient(m.getKa(), Double3.ONE),
                coefficient(m.getKd(), null),
                coefficient(m.getKs(), null),
                m.getShininess() == 0 ? null : m.getShininess(),
                coefficient(m.getKr(), null),
                coefficient(m.getKt(), null),
                m.getIndexOfRefraction() == 1 ? null : m.getIndexOfRefraction(),
                m.getRoughness() == 0 ? null : m.getRoughness());
        if (uses.getOrDefault(m, 0) < 2) return MaterialRef.of(d);
        String name = materialNames.computeIfAbsent(m, k -> "material-" + (materials.size() + 1));
        materials.putIfAbsent(name, d);
        return MaterialRef.named(name);
    }

    private static Coefficient coefficient(Double3 k, Double3 omitted) {
        if (k.equals(omitted) || (omitted == null && k.isZero())) return null;
        return new Coefficient(k.d1, k.d2, k.d3);
    }

    private static LightDocument light(LightSource light) {
        if (light instanceof DirectionalLight d) {
            return new DirectionalLightDocument(vec(d.getIntensity(Point.ZERO)), vec(d.getDirection()));
        }
        if (light instanceof PointLight p) {
            Double radius = p.getRadius() == 0 ? null : p.getRadius();
            Integer samples = p.getNumSamples() == 1 ? null : p.getNumSamples();
            Double range = Double.isFinite(p.getRange()) ? p.getRange() : null;
            if (light instanceof SpotLight s) {
                return new SpotLightDocument(
                        vec(s.getBaseIntensity()),
                        vec(s.getPosition()),
                        vec(s.getDirection()),
                        s.getNarrowBeam() == 1 ? null : s.getNarrowBeam(),
                        s.getKc(),
                        s.getKl(),
                        s.getKq(),
                        radius,
                        samples,
                        range);
            }
            return new PointLightDocument(
                    vec(p.getBaseIntensity()),
                    vec(p.getPosition()),
                    p.getKc(),
                    p.getKl(),
                    p.getKq(),
                    radius,
                    samples,
                    range);
        }
        throw new IllegalArgumentException("a " + light.getClass().getName() + " cannot be written to a scene file");
    }

    private static CameraDocument camera(Camera c) {
        DepthOfFieldDocument dof = c.getFocalDistance() > 0
                ? new DepthOfFieldDocument(
                        c.getFocalDistance(),
                        c.getApertureRadius(),
                        c.getApertureSampling().getSampleCount())
                : null;
        return new CameraDocument(
                vec(c.getLocation()),
                null,
                vec(c.getDirection()),
                vec(c.getUp()),
                c.getVpDistance(),
                c.getVpWidth(),
                c.getVpHeight(),
                dof);
    }

    private static RenderDocument render(Camera c) {
        SamplingConfig aa = c.getSamplingConfig();
        SamplingDocument sampling = aa.getSampleCount() == 1
                ? null
                : new SamplingDocument(
                        aa.getSampleCount(),
                        aa.getShape(),
                        aa.getPattern(),
                        aa.isAdaptive() ? aa.getAdaptiveThreshold() : null);
        RenderSettings s = c.getRenderSettings();
        RenderSettings d = RenderSettings.DEFAULT;
        return new RenderDocument(
                c.getNx(),
                c.getNy(),
                sampling,
                null,
                s.useBvh() ? null : false,
                s.maxLevel() == d.maxLevel() ? null : s.maxLevel(),
                s.shadowPattern() == d.shadowPattern() ? null : s.shadowPattern(),
                s.adaptiveShadows() ? true : null,
                s.glossySampling().getSampleCount() == d.glossySampling().getSampleCount()
                        ? null
                        : s.glossySampling().getSampleCount(),
                s.lightCutoff() == d.lightCutoff() ? null : s.lightCutoff(),
                c.getProgressive() == null || c.getProgressive().targetError() == 0
                        ? null
                        : c.getProgressive().targetError(),
                c.getProgressive() == null || c.getProgressive().timeBudgetSeconds() == 0
                        ? null
                        : c.getProgressive().timeBudgetSeconds());
    }

    private static List<Vec3> vertices(Polygon p) {
        return p.getVertices().stream().map(SceneExporter::vec).toList();
    }

    private static AxisDocument axis(Ray axis) {
        return new AxisDocument(vec(axis.getHead()), vec(axis.getDirection()));
    }

    private static Vec3 vec(Point p) {
        return new Vec3(p.x, p.y, p.z);
    }

    private static Vec3 vec(Color c) {
        return new Vec3(c.getR(), c.getG(), c.getB());
    }
}
