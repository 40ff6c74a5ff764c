package renderer;

import geometries.Accelerator;
import geometries.Geometry;
import geometries.HitRecord;
import lighting.LightSource;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.sampling.SampleStream;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SuperSamplingBlackboard;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * Whitted-style ray tracing with Phong shading: emission, ambient light times kA, and per light a diffuse
 * {@code kD |n.l|} and specular {@code kS max(0, -v.r)^shininess} term scaled by the light's visibility; then
 * mirror reflection (kR) and refraction by Snell's law (kT, index of refraction, total internal reflection),
 * recursing to {@link RenderSettings#maxLevel()} while the accumulated attenuation stays above
 * {@link RenderSettings#minAttenuation()}.
 *
 * <p>Visibility is the transmittance of the shadow segment: opaque occluders block, transparent ones attenuate by
 * their kT. A light with a radius is a disk facing the shaded point, sampled by a beam of shadow rays (soft
 * shadows), optionally adaptively. Rough materials spread reflected and refracted rays over a cone (glossy and
 * frosted surfaces); only the first rough bounce of a path splits into a beam, deeper ones take one random ray.
 *
 * <p>All secondary rays start at {@link SurfacePoint#spawnOrigin}, offset by the hit point's error bound.
 */
public class SimpleRayTracer extends RayTracerBase {
    private static final long REFLECTION = 1, REFRACTION = 2, SHADOW = 3;

    private RenderSettings settings;
    private Accelerator accelerator;
    private LightSource[] lights;
    private EffectPlan plan;
    private double minAttenuation;

    public SimpleRayTracer(Scene scene) {
        super(scene);
    }

    @Override
    public void prepare(RenderSettings settings) {
        this.settings = settings;
        this.accelerator =
                Accelerator.build(scene.geometries, settings.useBvh(), settings.bvhBins(), settings.bvhMaxLeafSize());
        this.lights = scene.lights.toArray(new LightSource[0]);
        this.plan = EffectPlan.of(scene, settings);
        this.minAttenuation = settings.minAttenuation();
    }

    @Override
    public boolean isPrepared() {
        return accelerator != null;
    }

    @Override
    public String describePlan() {
        return plan == null ? "" : plan.describe();
    }

    @Override
    public double preparationSeconds() {
        return accelerator == null ? 0 : accelerator.buildSeconds();
    }

    /** The compiled geometry of the last {@link #prepare} (for statistics and benchmarks). */
    public Accelerator getAccelerator() {
        return accelerator;
    }

    @Override
    public Color traceRay(Ray ray, TraceContext context, long pathSeed) {
        return trace(ray, context, pathSeed, settings.maxLevel(), Double3.ONE, true);
    }

    private Color trace(Ray ray, TraceContext ctx, long path, int level, Double3 k, boolean maySplit) {
        HitRecord hit = ctx.hit.reset();
        if (!accelerator.intersect(ray, 0, Double.POSITIVE_INFINITY, hit)) return scene.background;
        hit.geometry.completeHit(ray, hit);
        return shade(new SurfacePoint(hit), ray, ctx, path, level, k, maySplit);
    }

    private Color shade(SurfacePoint sp, Ray ray, TraceContext ctx, long path, int level, Double3 k, boolean maySplit) {
        Geometry geometry = sp.geometry;
        Material material = geometry.getMaterial();
        Color color =
                geometry.getEmission().add(scene.ambientLight.getIntensity().scale(material.getKa()));
        Vector v = ray.getDirection();
        Vector n = sp.shadingNormal;
        double nv = n.dotProduct(v);
        if (nv == 0) return color; // grazing: the surface is seen edge-on
        color = addLocalEffects(color, sp, material, v, n, nv, ctx, path);
        if (level > 1) color = addGlobalEffects(color, sp, material, v, n, nv, ctx, path, level, k, maySplit);
        return color;
    }

    // ------------------------------------------------------------------ direct light

    private Color addLocalEffects(
            Color color, SurfacePoint sp, Material m, Vector v, Vector n, double nv, TraceContext ctx, long path) {
        boolean responds = !m.getKd().isZero() || !m.getKs().isZero();
        double r = 0, g = 0, b = 0;
        for (int li = 0; li < lights.length; li++) {
            LightSource light = lights[li];
            Point p = sp.point;
            if (light.getDistance(p) == 0) continue; // the point is the light itself
            Vector l = light.getL(p);
            double nl = n.dotProduct(l);
            boolean facing = nl * nv > 0; // light and viewer on the same side of the surface
            Color intensity = light.getIntensity(p);
            boolean contributes = facing && responds && !intensity.isBlack();
            if (!contributes && plan.planning) continue;
            Double3 transmittance = plan.shadows ? visibility(light, li, sp, l, ctx, path) : Double3.ONE;
            if (!contributes || transmittance.isZero()) continue;
            Double3 kD = m.getKd(), kS = m.getKs();
            double diffuse = Math.abs(nl);
            double specular = 0;
            if (!kS.isZero()) {
                // r = l - 2(l.n)n; the highlight is where -v.r approaches 1.
                double minusVr = -(v.dotProduct(l) - 2 * nl * nv);
                if (minusVr > 0) specular = Math.pow(minusVr, m.getShininess());
            }
            double ir = intensity.getR() * transmittance.d1;
            double ig = intensity.getG() * transmittance.d2;
            double ib = intensity.getB() * transmittance.d3;
            r += ir * (kD.d1 * diffuse + kS.d1 * specular);
            g += ig * (kD.d2 * diffuse + kS.d2 * specular);
            b += ib * (kD.d3 * diffuse + kS.d3 * specular);
        }
        return color.add(new Color(r, g, b));
    }

    /** Fraction of {@code light} reaching the point: transmittance of one shadow ray, or averaged over a disk. */
    private Double3 visibility(
            LightSource light, int lightIndex, SurfacePoint sp, Vector l, TraceContext ctx, long path) {
        Point position = light.getPosition();
        if (position == null || !light.isSoft()) {
            return position == null
                    ? shadowToward(sp, -l.x, -l.y, -l.z, Double.POSITIVE_INFINITY, ctx)
                    : shadowTo(sp, position.x, position.y, position.z, ctx);
        }
        // A disk of the light's radius facing the point, sampled by a beam of shadow rays.
        int count = light.getNumSamples();
        double diameter = 2 * light.getRadius();
        Vector e1 = l.perpendicular();
        Vector e2 = l.crossProduct(e1);
        long seed = SampleStream.mix(SampleStream.mix(path, SHADOW), lightIndex);
        double[] offsets = ctx.shadowOffsets(count);
        if (settings.adaptiveShadows()) {
            // Probe the centre and a ring on the rim first: an occluder edge that crosses the disk almost surely
            // separates two of them, so agreement means the point is fully lit, in the umbra, or behind the same
            // glass from every part of the disk.
            int probes = Math.max(5, (int) Math.round(Math.sqrt(count)));
            if (probes < count) {
                SuperSamplingBlackboard.getProbeOffsets(probes, ctx.random.reset(seed), offsets);
                Double3 probe = diskVisibility(sp, position, e1, e2, diameter, probes, offsets, ctx);
                if (ctx.diskUniform) {
                    ctx.counters.samplesSaved += count - probes;
                    return probe;
                }
                seed = SampleStream.mix(seed, 1);
            }
        }
        SuperSamplingBlackboard.getSampleOffsets(
                count, TargetShape.CIRCLE, settings.shadowPattern(), ctx.random.reset(seed), offsets);
        return diskVisibility(sp, position, e1, e2, diameter, count, offsets, ctx);
    }

    /**
     * Mean transmittance of the shadow rays toward {@code count} points of the disk given by {@code offsets}. When
     * every ray has the same transmittance (all clear, all blocked, or all through the same glass) it is returned
     * exactly, not as a sum divided by the count, so a soft light that nothing partly hides shades exactly as the
     * hard light; {@link TraceContext#diskUniform} tells whether that was the case.
     */
    private Double3 diskVisibility(
            SurfacePoint sp,
            Point c,
            Vector e1,
            Vector e2,
            double diameter,
            int count,
            double[] offsets,
            TraceContext ctx) {
        double r = 0, g = 0, b = 0;
        Double3 first = null;
        boolean uniform = true;
        for (int i = 0; i < count; i++) {
            double a = offsets[2 * i] * diameter, bb = offsets[2 * i + 1] * diameter;
            double qx = c.x + a * e1.x + bb * e2.x;
            double qy = c.y + a * e1.y + bb * e2.y;
            double qz = c.z + a * e1.z + bb * e2.z;
            Double3 t = shadowTo(sp, qx, qy, qz, ctx);
            if (first == null) first = t;
            else if (uniform && !t.equals(first)) uniform = false;
            r += t.d1;
            g += t.d2;
            b += t.d3;
        }
        ctx.diskUniform = uniform;
        if (uniform) return first;
        return new Double3(r / count, g / count, b / count);
    }

    /** Transmittance of the segment from the surface to the point (x, y, z). */
    private Double3 shadowTo(SurfacePoint sp, double x, double y, double z, TraceContext ctx) {
        Point p = sp.point;
        double dx = x - p.x, dy = y - p.y, dz = z - p.z;
        if (dx == 0 && dy == 0 && dz == 0) return Double3.ONE;
        Point origin = sp.spawnOrigin(dx, dy, dz);
        double ox = x - origin.x, oy = y - origin.y, oz = z - origin.z;
        if (ox == 0 && oy == 0 && oz == 0) return Double3.ONE;
        Vector direction = new Vector(ox, oy, oz);
        ctx.counters.shadow++;
        return accelerator.transmittance(new Ray(origin, direction), 0, direction.length(), ctx.shadowHit);
    }

    /** Transmittance along a direction up to {@code tMax} (directional lights). */
    private Double3 shadowToward(SurfacePoint sp, double dx, double dy, double dz, double tMax, TraceContext ctx) {
        Point origin = sp.spawnOrigin(dx, dy, dz);
        ctx.counters.shadow++;
        return accelerator.transmittance(new Ray(origin, new Vector(dx, dy, dz)), 0, tMax, ctx.shadowHit);
    }

    // ------------------------------------------------------------------ reflection and refraction

    private Color addGlobalEffects(
            Color color,
            SurfacePoint sp,
            Material m,
            Vector v,
            Vector n,
            double nv,
            TraceContext ctx,
            long path,
            int level,
            Double3 k,
            boolean maySplit) {
        Double3 kR = m.getKr(), kT = m.getKt();
        if (plan.reflection && (!kR.isZero() || !plan.planning)) {
            Double3 kk = k.product(kR);
            boolean weightless = kR.isZero(); // fired only with planning off, to show planning changes nothing
            if (weightless || !kk.lowerThan(minAttenuation)) {
                Vector reflected = Optics.reflect(v, n, nv);
                Color c = beam(
                        sp,
                        reflected,
                        m.getRoughness(),
                        false,
                        ctx,
                        SampleStream.mix(path, REFLECTION),
                        weightless ? 1 : level - 1,
                        kk,
                        maySplit);
                if (!weightless) color = color.add(c.scale(kR));
            }
        }
        if (plan.refraction && (!kT.isZero() || !plan.planning)) {
            Double3 kk = k.product(kT);
            boolean weightless = kT.isZero();
            if (weightless || !kk.lowerThan(minAttenuation)) {
                Vector refracted = Optics.refract(v, n, nv, m.getIndexOfRefraction());
                Color c = beam(
                        sp,
                        refracted,
                        m.getRoughness(),
                        true,
                        ctx,
                        SampleStream.mix(path, REFRACTION),
                        weightless ? 1 : level - 1,
                        kk,
                        maySplit);
                if (!weightless) color = color.add(c.scale(kT));
            }
        }
        return color;
    }

    /**
     * The colour arriving along {@code ideal}: one ray for smooth surfaces, a beam spread over a cone of radius
     * {@code roughness} (at unit distance) for rough ones.
     */
    private Color beam(
            SurfacePoint sp,
            Vector ideal,
            double roughness,
            boolean refraction,
            TraceContext ctx,
            long path,
            int level,
            Double3 k,
            boolean maySplit) {
        SamplingConfig glossy = settings.glossySampling();
        if (!(roughness > 0) || !plan.glossy || !glossy.isEnabled()) {
            return secondary(sp, ideal, refraction, false, ctx, path, level, k, maySplit);
        }
        Vector e1 = ideal.perpendicular();
        Vector e2 = ideal.crossProduct(e1);
        double diameter = 2 * roughness;
        int count;
        double[] offsets;
        if (maySplit) {
            count = glossy.getSampleCount();
            offsets = ctx.glossyOffsets(count);
            SuperSamplingBlackboard.getSampleOffsets(
                    count, TargetShape.CIRCLE, glossy.getPattern(), ctx.random.reset(path), offsets);
        } else {
            // Below the first rough bounce: one random ray in the cone, so the cost stays linear in depth. (Its own
            // array: the beam above this one is still reading the shared buffer.)
            count = 1;
            offsets = new double[2];
            SuperSamplingBlackboard.randomPointInDisk(ctx.random.reset(path), offsets, 0);
        }
        ColorAverage average = new ColorAverage();
        for (int i = 0; i < count; i++) {
            double a = offsets[2 * i] * diameter, b = offsets[2 * i + 1] * diameter;
            double dx = ideal.x + a * e1.x + b * e2.x;
            double dy = ideal.y + a * e1.y + b * e2.y;
            double dz = ideal.z + a * e1.z + b * e2.z;
            // Keep the ray on the side of the surface the ideal ray leaves toward.
            Vector ng = sp.normal;
            double side = ideal.x * ng.x + ideal.y * ng.y + ideal.z * ng.z;
            double d = dx * ng.x + dy * ng.y + dz * ng.z;
            if (d * side < 0) {
                dx -= 2 * d * ng.x;
                dy -= 2 * d * ng.y;
                dz -= 2 * d * ng.z;
            }
            if (dx == 0 && dy == 0 && dz == 0) continue;
            Vector direction = new Vector(dx, dy, dz);
            average.add(secondary(sp, direction, refraction, true, ctx, SampleStream.mix(path, i), level, k, false));
        }
        return average.mean();
    }

    private Color secondary(
            SurfacePoint sp,
            Vector direction,
            boolean refraction,
            boolean rough,
            TraceContext ctx,
            long path,
            int level,
            Double3 k,
            boolean maySplit) {
        if (refraction) ctx.counters.refraction++;
        else ctx.counters.reflection++;
        if (rough) ctx.counters.glossy++;
        Point origin = sp.spawnOrigin(direction.x, direction.y, direction.z);
        return trace(new Ray(origin, direction), ctx, path, level, k, maySplit);
    }
}
