package renderer;

import geometries.Accelerator;
import geometries.HitRecord;
import lighting.LightSource;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Ray;
import primitives.ReusableRay;
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
 * A light whose unshadowed contribution is too faint to matter is not sampled at all, within the budget of
 * {@link RenderSettings#lightCutoff()} per camera sample.
 *
 * <p>All secondary rays start at {@link SurfacePoint#spawn}, offset by the hit point's error bound.
 *
 * <p>This is the render loop's hot path, and it allocates nothing: rays are the thread's {@link ReusableRay}s,
 * shaded points its per-level {@link SurfacePoint}s, and colours travel as three doubles (results come back in
 * {@link TraceContext#red} and its siblings). The arithmetic is that of the friendly API (Vector, Color, Double3)
 * operation for operation, so images are the same bit for bit.
 */
public class SimpleRayTracer extends RayTracerBase {
    private static final long REFLECTION = 1, REFRACTION = 2;
    /** The stream of a progressive render's glossy beams (mixed with the level). */
    private static final long GLOSSY_SEQUENCE = 4;

    private RenderSettings settings;
    private Accelerator accelerator;
    private LightSource[] lights;
    private EffectPlan plan;
    /** The direct light at a shading point, with its shadow rays. */
    private DirectLightEstimator directLight;

    private double minAttenuation;
    /** Whether the direct light at a first hit is the same for every sample that shades it: hard lights only. */
    private boolean directRepeats;

    private double ambientR, ambientG, ambientB;

    /**
     * A tracer of {@code scene}; call {@link #prepare} before tracing.
     *
     * @param scene the scene to trace; not null
     */
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
        this.directLight = new DirectLightEstimator(lights, plan, settings, accelerator);
        directRepeats = true;
        for (LightSource light : lights) directRepeats &= DirectLightEstimator.castsOneShadowRay(light);
        this.minAttenuation = settings.minAttenuation();
        Color ambient = scene.ambientLight.getIntensity();
        ambientR = ambient.getR();
        ambientG = ambient.getG();
        ambientB = ambient.getB();
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

    /**
     * The compiled geometry of the last {@link #prepare} (for statistics and benchmarks).
     *
     * @return the search structure, or null before the first {@link #prepare}
     */
    public Accelerator getAccelerator() {
        return accelerator;
    }

    @Override
    public void trace(Ray ray, TraceContext context, long pathSeed) {
        context.cutoffBudget = plan.lightCutoff;
        trace(ray, context, pathSeed, settings.maxLevel(), 1, 1, 1, true);
    }

    /** Shades the first hit of the previous {@link #trace} again (kept in the first level's surface point). */
    @Override
    public void traceAgain(Ray ray, TraceContext context, long pathSeed) {
        context.cutoffBudget = plan.lightCutoff;
        int level = settings.maxLevel();
        if (context.firstRayMissed) {
            context.setColor(scene.background.getR(), scene.background.getG(), scene.background.getB());
            return;
        }
        shade(context.surface(level), ray.dx(), ray.dy(), ray.dz(), context, pathSeed, level, 1, 1, 1, true);
    }

    /**
     * A batch where the first hit's shading fires only shadow rays, and no adaptive probes (which decide per sample):
     * its colour is then linear in the shadow beams' mean transmittance, and the samples' beams, taken together, give
     * the mean of their colours. Each soft light's beam takes all the samples' points at once; a hard light's single
     * ray is the same for every sample, and is fired once.
     */
    @Override
    public boolean traceAgainBatch(Ray ray, TraceContext context, long pathSeed, int samples) {
        if (settings.adaptiveShadows()) return false;
        int level = settings.maxLevel();
        if (!context.firstRayMissed && level > 1) {
            Material m = context.surface(level).geometry.getMaterial();
            if (reflects(m) || refracts(m)) return false;
        }
        context.sequenceBatch = samples;
        try {
            traceAgain(ray, context, pathSeed);
        } finally {
            context.sequenceBatch = 1;
        }
        return true;
    }

    /** Whether shading a surface of material {@code m} fires reflection rays (when its level allows). */
    private boolean reflects(Material m) {
        return plan.reflection && (!m.getKr().isZero() || !plan.planning);
    }

    /** Whether shading a surface of material {@code m} fires refraction rays (when its level allows). */
    private boolean refracts(Material m) {
        return plan.refraction && (!m.getKt().isZero() || !plan.planning);
    }

    /**
     * The colour along {@code ray} into {@code ctx.red, green, blue}. {@code kr, kg, kb} is the attenuation the
     * path has accumulated (the weight of this colour in the pixel).
     *
     * <p>Each level shades into its own {@link SurfacePoint}: the levels active at once are distinct, since a
     * secondary ray goes one level down, or straight to level 1 (a weightless ray with planning off), where
     * nothing recurses.
     */
    private void trace(
            Ray ray, TraceContext ctx, long path, int level, double kr, double kg, double kb, boolean maySplit) {
        SurfacePoint sp = hit(ray, ctx, level);
        if (sp == null) {
            ctx.setColor(scene.background.getR(), scene.background.getG(), scene.background.getB());
            return;
        }
        shade(sp, ray.dx(), ray.dy(), ray.dz(), ctx, path, level, kr, kg, kb, maySplit);
    }

    /**
     * The first hit along {@code ray}, in level {@code level}'s surface point, or null where the ray meets nothing.
     * At the first level it is kept for {@link #traceAgain}.
     */
    private SurfacePoint hit(Ray ray, TraceContext ctx, int level) {
        HitRecord hit = ctx.hit.reset();
        // Only textured meshes set texture coordinates: zeroed here, a texture elsewhere reads a fixed texel
        // rather than the previous ray's (which would make images depend on the ray order).
        hit.texU = 0;
        hit.texV = 0;
        boolean found = accelerator.intersect(ray, 0, Double.POSITIVE_INFINITY, hit);
        if (level == settings.maxLevel()) {
            ctx.firstRayMissed = !found; // for traceAgain
            ctx.directKept = false; // a new first hit
            ctx.termsKept = false;
        }
        if (!found) return null;
        hit.complete(ray);
        return ctx.surface(level).set(hit);
    }

    /** Finds the first hit along {@code ray}, unshaded, for the {@link #traceAgain} and batches that follow. */
    @Override
    public boolean locate(Ray ray, TraceContext context) {
        hit(ray, context, settings.maxLevel());
        return true;
    }

    private void shade(
            SurfacePoint sp,
            double vx,
            double vy,
            double vz,
            TraceContext ctx,
            long path,
            int level,
            double kr,
            double kg,
            double kb,
            boolean maySplit) {
        Material m = sp.geometry.getMaterial();
        Color emission = sp.geometry.getEmission();
        Double3 kA = m.getKa();
        double r = emission.getR() + ambientR * kA.d1;
        double g = emission.getG() + ambientG * kA.d2;
        double b = emission.getB() + ambientB * kA.d3;
        double nv = sp.snx * vx + sp.sny * vy + sp.snz * vz;
        if (nv == 0) { // grazing: the surface is seen edge-on
            ctx.setColor(r, g, b);
            return;
        }
        if (directRepeats && level == settings.maxLevel()) {
            directAtFirstHit(sp, m, vx, vy, vz, nv, ctx, path);
        } else {
            directLight.estimate(
                    sp, m, vx, vy, vz, nv, ctx, path, Math.max(kr, Math.max(kg, kb)), level == settings.maxLevel());
        }
        r += ctx.red;
        g += ctx.green;
        b += ctx.blue;
        if (level > 1) {
            Double3 kR = m.getKr(), kT = m.getKt();
            if (reflects(m)) {
                double kkr = kr * kR.d1, kkg = kg * kR.d2, kkb = kb * kR.d3;
                boolean weightless = kR.isZero(); // fired only with planning off, to show planning changes nothing
                if (weightless || !lowerThan(kkr, kkg, kkb, minAttenuation)) {
                    double f = 2 * nv; // Optics.reflect
                    beam(
                            sp,
                            vx - f * sp.snx,
                            vy - f * sp.sny,
                            vz - f * sp.snz,
                            m.getRoughness(),
                            false,
                            ctx,
                            SampleStream.mix(path, REFLECTION),
                            weightless ? 1 : level - 1,
                            kkr,
                            kkg,
                            kkb,
                            maySplit);
                    if (!weightless) {
                        r += ctx.red * kR.d1;
                        g += ctx.green * kR.d2;
                        b += ctx.blue * kR.d3;
                    }
                }
            }
            if (refracts(m)) {
                double kkr = kr * kT.d1, kkg = kg * kT.d2, kkb = kb * kT.d3;
                boolean weightless = kT.isZero();
                if (weightless || !lowerThan(kkr, kkg, kkb, minAttenuation)) {
                    double[] d = ctx.direction;
                    Optics.refract(vx, vy, vz, sp.snx, sp.sny, sp.snz, nv, m.getIndexOfRefraction(), d);
                    beam(
                            sp,
                            d[0],
                            d[1],
                            d[2],
                            m.getRoughness(),
                            true,
                            ctx,
                            SampleStream.mix(path, REFRACTION),
                            weightless ? 1 : level - 1,
                            kkr,
                            kkg,
                            kkb,
                            maySplit);
                    if (!weightless) {
                        r += ctx.red * kT.d1;
                        g += ctx.green * kT.d2;
                        b += ctx.blue * kT.d3;
                    }
                }
            }
        }
        ctx.setColor(r, g, b);
    }

    /**
     * The direct light at the first hit into {@code ctx.red, green, blue}, kept for the samples that shade the same hit
     * again ({@link #traceAgain}, progressive samples through a pixel's centre): with hard lights only, it depends on
     * nothing a sample changes (its one shadow ray per light is the same ray), so every sample after the first takes
     * the first one's values, and the light cut-off's budget as it left it. (The accuracy report's glossy reflection,
     * progressive: 0.82-0.87x the time, 137,292 shadow rays -> 17,982 at RMSE 1.)
     */
    private void directAtFirstHit(
            SurfacePoint sp, Material m, double vx, double vy, double vz, double nv, TraceContext ctx, long path) {
        if (ctx.directKept) {
            ctx.setColor(ctx.directR, ctx.directG, ctx.directB);
            ctx.cutoffBudget = ctx.directCutoffLeft;
            return;
        }
        directLight.estimate(sp, m, vx, vy, vz, nv, ctx, path, 1, false);
        ctx.directR = ctx.red;
        ctx.directG = ctx.green;
        ctx.directB = ctx.blue;
        ctx.directCutoffLeft = ctx.cutoffBudget;
        ctx.directKept = true;
    }

    private static boolean lowerThan(double r, double g, double b, double limit) {
        return r < limit && g < limit && b < limit;
    }

    // ------------------------------------------------------------------ reflection and refraction

    /**
     * The colour arriving along {@code ideal} into {@code ctx.red, green, blue}: one ray for smooth surfaces, a
     * beam spread over a cone of radius {@code roughness} (at unit distance) for rough ones.
     */
    private void beam(
            SurfacePoint sp,
            double ix,
            double iy,
            double iz,
            double roughness,
            boolean refraction,
            TraceContext ctx,
            long path,
            int level,
            double kr,
            double kg,
            double kb,
            boolean maySplit) {
        SamplingConfig glossy = settings.glossySampling();
        if (!(roughness > 0) || !plan.glossy || !glossy.isEnabled()) {
            secondary(sp, ix, iy, iz, refraction, false, ctx, path, level, kr, kg, kb, maySplit);
            return;
        }
        // The cone's frame, kept in locals: the secondary rays below reuse this level's point for deeper beams.
        sp.basis(ix, iy, iz);
        double e1x = sp.e1x, e1y = sp.e1y, e1z = sp.e1z, e2x = sp.e2x, e2y = sp.e2y, e2z = sp.e2z;
        double diameter = 2 * roughness;
        int count;
        double[] offsets;
        if (maySplit) {
            count = glossy.getSampleCount();
            offsets = ctx.glossyOffsets(count);
            if (!ctx.continueSequence(GLOSSY_SEQUENCE, level, count, TargetShape.CIRCLE, offsets)) {
                SuperSamplingBlackboard.getSampleOffsets(
                        count, TargetShape.CIRCLE, glossy.getPattern(), ctx.random.reset(path), offsets);
            }
        } else {
            // Below the first rough bounce: one random ray in the cone, so the cost stays linear in depth. (Its own
            // buffer: the beam above this one is still reading the shared one; this one is read before recursing.)
            count = 1;
            offsets = ctx.roughOffset;
            SuperSamplingBlackboard.randomPointInDisk(ctx.random.reset(path), offsets, 0);
        }
        ColorAverage average = sp.beamAverage.reset();
        for (int i = 0; i < count; i++) {
            double a = offsets[2 * i] * diameter, b = offsets[2 * i + 1] * diameter;
            double dx = ix + a * e1x + b * e2x;
            double dy = iy + a * e1y + b * e2y;
            double dz = iz + a * e1z + b * e2z;
            // Keep the ray on the side of the surface the ideal ray leaves toward.
            double side = ix * sp.nx + iy * sp.ny + iz * sp.nz;
            double d = dx * sp.nx + dy * sp.ny + dz * sp.nz;
            if (d * side < 0) {
                dx -= 2 * d * sp.nx;
                dy -= 2 * d * sp.ny;
                dz -= 2 * d * sp.nz;
            }
            if (dx == 0 && dy == 0 && dz == 0) continue;
            secondary(sp, dx, dy, dz, refraction, true, ctx, SampleStream.mix(path, i), level, kr, kg, kb, false);
            average.add(ctx);
        }
        average.meanInto(ctx);
    }

    private void secondary(
            SurfacePoint sp,
            double dx,
            double dy,
            double dz,
            boolean refraction,
            boolean rough,
            TraceContext ctx,
            long path,
            int level,
            double kr,
            double kg,
            double kb,
            boolean maySplit) {
        if (refraction) ctx.counters.refraction++;
        else ctx.counters.reflection++;
        if (rough) ctx.counters.glossy++;
        sp.spawn(dx, dy, dz);
        ReusableRay ray = ctx.ray.set(sp.originX, sp.originY, sp.originZ, dx, dy, dz);
        trace(ray, ctx, path, level, kr, kg, kb, maySplit);
    }
}
