package renderer;

import geometries.Accelerator;
import geometries.HitRecord;
import java.util.ArrayList;
import java.util.List;
import lighting.LightSource;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Finds edges inside a pixel by tracing its own rays: an edge is where the surfaces a path meets (directly and
 * through mirrors and glass) or their hard-shadow visibility of the lights change. Between such edges a Whitted
 * image varies smoothly, so supersampling can only change a pixel noticeably where its samples straddle one. The
 * rays are those of the anti-aliasing GRID: the centres of a k x k subdivision of the pixel.
 */
final class EdgeProbe {
    private final Scene scene;
    private final Accelerator accelerator;
    private final Camera camera;
    private final HitRecord shadowHit = new HitRecord();

    EdgeProbe(Scene scene, Camera camera) {
        this.scene = scene;
        this.accelerator = Accelerator.build(scene.geometries, true);
        this.camera = camera;
    }

    /** Whether the k x k GRID samples of pixel (x, y) do not all see the same surfaces under the same shadows. */
    boolean edgeInside(int x, int y, int k) {
        List<Object> first = null;
        for (int a = 0; a < k; a++) {
            for (int b = 0; b < k; b++) {
                // Pixel centres of an image k times finer are exactly the GRID sample positions of this pixel.
                Ray ray = camera.constructRay(k * camera.getNx(), k * camera.getNy(), k * x + b, k * y + a);
                List<Object> signature = new ArrayList<>();
                follow(ray, RenderSettings.DEFAULT.maxLevel(), Double3.ONE, signature);
                if (first == null) first = signature;
                else if (!first.equals(signature)) return true;
            }
        }
        return false;
    }

    /** Appends what the path sees: each surface hit (by identity) and the transmittance toward every light. */
    private void follow(Ray ray, int level, Double3 k, List<Object> signature) {
        HitRecord hit = new HitRecord();
        if (!accelerator.intersect(ray, 0, Double.POSITIVE_INFINITY, hit)) {
            signature.add("background");
            return;
        }
        hit.complete(ray);
        SurfacePoint sp = new SurfacePoint(hit);
        signature.add(
                System.identityHashCode(sp.geometry) + "/" + System.identityHashCode(hit.instance) + "/" + hit.part);
        Vector v = ray.getDirection(), n = sp.shadingNormal();
        double nv = n.dotProduct(v);
        for (LightSource light : scene.lights) {
            // As the tracer does: a light on the other side of the surface from the viewer is not looked for.
            boolean facing = n.dotProduct(light.getL(sp.point())) * nv > 0;
            signature.add(facing ? visibility(sp, light) : "behind");
        }
        if (level <= 1 || nv == 0) return;
        Material m = sp.geometry.getMaterial();
        Double3 kr = k.product(m.getKr()), kt = k.product(m.getKt());
        if (!m.getKr().isZero() && !kr.lowerThan(RenderSettings.DEFAULT.minAttenuation())) {
            Vector r = Optics.reflect(v, n, nv);
            follow(new Ray(sp.spawnOrigin(r.x, r.y, r.z), r), level - 1, kr, signature);
        }
        if (!m.getKt().isZero() && !kt.lowerThan(RenderSettings.DEFAULT.minAttenuation())) {
            Vector t = Optics.refract(v, n, nv, m.getIndexOfRefraction());
            follow(new Ray(sp.spawnOrigin(t.x, t.y, t.z), t), level - 1, kt, signature);
        }
    }

    /** Transmittance of the hard shadow ray toward the light (its centre, or along a directional light). */
    private Double3 visibility(SurfacePoint sp, LightSource light) {
        Point p = sp.point(), c = light.getPosition();
        if (c == null) {
            Vector l = light.getL(p);
            Point origin = sp.spawnOrigin(-l.x, -l.y, -l.z);
            return accelerator.transmittance(
                    new Ray(origin, new Vector(-l.x, -l.y, -l.z)), 0, Double.POSITIVE_INFINITY, shadowHit);
        }
        Point origin = sp.spawnOrigin(c.x - p.x, c.y - p.y, c.z - p.z);
        Vector d = new Vector(c.x - origin.x, c.y - origin.y, c.z - origin.z);
        return accelerator.transmittance(new Ray(origin, d), 0, d.length(), shadowHit);
    }
}
