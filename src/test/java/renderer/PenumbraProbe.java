package renderer;

import geometries.Accelerator;
import geometries.HitRecord;
import lighting.LightSource;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Decides, by tracing its own rays, whether a pixel sees a penumbra: whether along the pixel's central camera ray
 * (followed through mirrors and glass as the tracer does) some surface point sees part of a disk light's area and
 * not the rest. Used to check that soft shadows change only such pixels.
 *
 * <p>Each light's disk (facing the point, as the tracer samples it) is probed at its centre and on rings of
 * points; the point is in a penumbra when those shadow rays do not all carry the same transmittance. The probes
 * are independent of the tracer's sample positions: a quick probe (4 rings of 16) finds ordinary penumbrae, a dense
 * one (24 rings of 96) also the faint slivers where an occluder hides only a few percent of the disk's rim, which a
 * tracer sample may still catch.
 */
final class PenumbraProbe {

    private final Scene scene;
    private final Accelerator accelerator;
    private final Camera camera;
    private final int maxLevel;
    private final double minAttenuation;
    private final HitRecord shadowHit = new HitRecord();

    /** Probes the scene as seen by {@code camera} with the recursion limits of the default render settings. */
    PenumbraProbe(Scene scene, Camera camera) {
        this.scene = scene;
        this.accelerator = Accelerator.build(scene.geometries, true);
        this.camera = camera;
        this.maxLevel = RenderSettings.DEFAULT.maxLevel();
        this.minAttenuation = RenderSettings.DEFAULT.minAttenuation();
    }

    /**
     * Whether pixel (x, y) looks, directly or through mirrors and glass, at a point in some light's penumbra, by the
     * quick probe or, if {@code dense}, the dense one.
     */
    boolean penumbral(int x, int y, boolean dense) {
        Ray ray = camera.constructRay(camera.getNx(), camera.getNy(), x, y);
        return dense ? walk(ray, maxLevel, Double3.ONE, 24, 96) : walk(ray, maxLevel, Double3.ONE, 4, 16);
    }

    private boolean walk(Ray ray, int level, Double3 k, int rings, int perRing) {
        HitRecord hit = new HitRecord();
        if (!accelerator.intersect(ray, 0, Double.POSITIVE_INFINITY, hit)) return false;
        hit.complete(ray);
        SurfacePoint sp = new SurfacePoint(hit);
        for (LightSource light : scene.lights) {
            if (light.isSoft() && mixed(sp, light, rings, perRing)) return true;
        }
        if (level <= 1) return false;
        Material m = sp.geometry.getMaterial();
        Vector v = ray.getDirection(), n = sp.shadingNormal();
        double nv = n.dotProduct(v);
        if (nv == 0) return false;
        Double3 kr = k.product(m.getKr()), kt = k.product(m.getKt());
        if (!m.getKr().isZero() && !kr.lowerThan(minAttenuation)) {
            Vector r = Optics.reflect(v, n, nv);
            if (walk(new Ray(sp.spawnOrigin(r.x, r.y, r.z), r), level - 1, kr, rings, perRing)) return true;
        }
        if (!m.getKt().isZero() && !kt.lowerThan(minAttenuation)) {
            Vector t = Optics.refract(v, n, nv, m.getIndexOfRefraction());
            return walk(new Ray(sp.spawnOrigin(t.x, t.y, t.z), t), level - 1, kt, rings, perRing);
        }
        return false;
    }

    /** Whether shadow rays from the point to the centre and rings of the light's disk disagree. */
    private boolean mixed(SurfacePoint sp, LightSource light, int rings, int perRing) {
        Point c = light.getPosition();
        Vector l = light.getL(sp.point());
        Vector e1 = l.perpendicular(), e2 = l.crossProduct(e1);
        Double3 first = transmittance(sp, c.x, c.y, c.z);
        for (int ring = 1; ring <= rings; ring++) {
            double r = light.getRadius() * ring / rings;
            for (int i = 0; i < perRing; i++) {
                // Rings turned against each other so the probes do not line up radially.
                double a = 2 * Math.PI * (i + 0.5 * ring) / perRing;
                double u = r * Math.cos(a), w = r * Math.sin(a);
                Double3 t = transmittance(
                        sp, c.x + u * e1.x + w * e2.x, c.y + u * e1.y + w * e2.y, c.z + u * e1.z + w * e2.z);
                if (!t.equals(first)) return true;
            }
        }
        return false;
    }

    private Double3 transmittance(SurfacePoint sp, double x, double y, double z) {
        Point p = sp.point();
        Point origin = sp.spawnOrigin(x - p.x, y - p.y, z - p.z);
        Vector d = new Vector(x - origin.x, y - origin.y, z - origin.z);
        return accelerator.transmittance(new Ray(origin, d), 0, d.length(), shadowHit);
    }
}
