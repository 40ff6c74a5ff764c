package renderer;

import geometries.Accelerator;
import geometries.HitRecord;
import lighting.LightSample;
import lighting.LightSource;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.ReusableRay;
import primitives.Texture;
import primitives.Util;
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
    private static final long REFLECTION = 1, REFRACTION = 2, SHADOW = 3;
    /** The stream of a progressive render's glossy beams (mixed with the level). */
    private static final long GLOSSY_SEQUENCE = 4;

    private RenderSettings settings;
    private Accelerator accelerator;
    private LightSource[] lights;
    private EffectPlan plan;
    private double minAttenuation;
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
        HitRecord hit = ctx.hit.reset();
        // Only textured meshes set texture coordinates: zeroed here, a texture elsewhere reads a fixed texel
        // rather than the previous ray's (which would make images depend on the ray order).
        hit.texU = 0;
        hit.texV = 0;
        boolean found = accelerator.intersect(ray, 0, Double.POSITIVE_INFINITY, hit);
        if (level == settings.maxLevel()) ctx.firstRayMissed = !found; // for traceAgain
        if (!found) {
            ctx.setColor(scene.background.getR(), scene.background.getG(), scene.background.getB());
            return;
        }
        hit.complete(ray);
        SurfacePoint sp = ctx.surface(level).set(hit);
        shade(sp, ray.dx(), ray.dy(), ray.dz(), ctx, path, level, kr, kg, kb, maySplit);
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
        addDirectLight(sp, m, vx, vy, vz, nv, ctx, path, Math.max(kr, Math.max(kg, kb)));
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

    private static boolean lowerThan(double r, double g, double b, double limit) {
        return r < limit && g < limit && b < limit;
    }

    // ------------------------------------------------------------------ direct light

    /**
     * The light of every light source reaching the point and sent toward the viewer, into {@code ctx.red, green,
     * blue}. {@code weight} is the largest channel of the path's attenuation: the cut-off counts a skipped light
     * at what it would have added to the pixel.
     *
     * <p>First every light's unshadowed contribution is found (no rays); then, with the light cut-off, the faintest
     * lights whose contributions add up to less than the sample's remaining budget are set aside; the others are
     * sampled with shadow rays, in light order; last the set-aside lights are added, each scaled by the fraction
     * of the sampled lights' light that got through (Ward's adaptive shadow testing, as in Radiance's direct
     * threshold): an estimate off by at most the light's own contribution, usually by far less.
     */
    private void addDirectLight(
            SurfacePoint sp,
            Material m,
            double vx,
            double vy,
            double vz,
            double nv,
            TraceContext ctx,
            long path,
            double weight) {
        Double3 kD = m.getKd(), kS = m.getKs();
        double kdR = kD.d1, kdG = kD.d2, kdB = kD.d3;
        Texture map = m.getKdMap();
        if (map != null) { // untextured materials pay only this test
            double[] texel = ctx.texel;
            map.lookup(sp.texU, sp.texV, texel);
            kdR *= texel[0];
            kdG *= texel[1];
            kdB *= texel[2];
        }
        boolean responds = kdR != 0 || kdG != 0 || kdB != 0 || !kS.isZero();
        boolean specularResponse = !kS.isZero();
        DirectLighting direct = ctx.direct(lights.length);
        direct.setAside = 0;
        for (int li = 0; li < lights.length; li++) {
            LightSample ls = direct.samples[li];
            lights[li].illuminate(sp.px, sp.py, sp.pz, ls);
            direct.state[li] = DirectLighting.SKIP;
            if (ls.distance == 0) continue; // the point is the light itself
            double nl = sp.snx * ls.lx + sp.sny * ls.ly + sp.snz * ls.lz;
            boolean facing = nl * nv > 0; // light and viewer on the same side of the surface
            boolean contributes = facing && responds && !ls.isBlack();
            if (!contributes && plan.planning) continue;
            double diffuse = Math.abs(nl);
            double specular = 0;
            if (specularResponse) {
                // r = l - 2(l.n)n; the highlight is where -v.r approaches 1.
                double minusVr = -((vx * ls.lx + vy * ls.ly + vz * ls.lz) - 2 * nl * nv);
                if (minusVr > 0) specular = Util.power(minusVr, m.getShininess());
            }
            // The material's response to the light, per unit of its intensity.
            double fr = kdR * diffuse + kS.d1 * specular;
            double fg = kdG * diffuse + kS.d2 * specular;
            double fb = kdB * diffuse + kS.d3 * specular;
            direct.set(li, contributes ? DirectLighting.CONTRIBUTES : DirectLighting.WEIGHTLESS, fr, fg, fb, weight);
        }
        if (plan.lightCutoff > 0) {
            ctx.cutoffBudget = direct.setAsideFaintest(ctx.cutoffBudget);
        }
        double r = 0, g = 0, b = 0;
        double unshadowed = 0, passed = 0;
        // The shadow rays start on the point's surface, offset toward the light's side: a flat surface cannot block
        // them, so the queries leave it out (on the street, 83% of the primitive tests within beams were of it).
        ctx.shadowHit.leaveSurface(sp.inInstance ? null : sp.geometry, sp.part);
        for (int li = 0; li < lights.length; li++) {
            int state = direct.state[li];
            if (state == DirectLighting.SKIP || state == DirectLighting.SET_ASIDE) continue;
            LightSource light = lights[li];
            LightSample ls = direct.samples[li];
            if (plan.shadows) {
                visibility(light, li, sp, ls, ctx, path, direct.occluders);
            } else {
                ctx.visibleR = ctx.visibleG = ctx.visibleB = 1;
            }
            if (state != DirectLighting.CONTRIBUTES || (ctx.visibleR == 0 && ctx.visibleG == 0 && ctx.visibleB == 0)) {
                if (state == DirectLighting.CONTRIBUTES) unshadowed += direct.sum(li);
                continue;
            }
            double ir = ls.r * ctx.visibleR;
            double ig = ls.g * ctx.visibleG;
            double ib = ls.b * ctx.visibleB;
            double dr = ir * direct.responseR[li], dg = ig * direct.responseG[li], db = ib * direct.responseB[li];
            r += dr;
            g += dg;
            b += db;
            unshadowed += direct.sum(li);
            passed += dr + dg + db;
        }
        if (direct.setAside > 0) {
            // The lights set aside pass light in the proportion the sampled ones did (all of it, with none sampled).
            double fraction = unshadowed > 0 ? passed / unshadowed : 1;
            for (int li = 0; li < lights.length; li++) {
                if (direct.state[li] != DirectLighting.SET_ASIDE) continue;
                r += direct.unshadowedR[li] * fraction;
                g += direct.unshadowedG[li] * fraction;
                b += direct.unshadowedB[li] * fraction;
                ctx.counters.lightsCutOff++;
                ctx.counters.shadowRaysCutOff += plan.shadows ? shadowRaysOf(lights[li]) : 0;
            }
        }
        ctx.setColor(r, g, b);
    }

    /** The fewest shadow rays a light costs per shading point: one, a disk's count, or its adaptive probes. */
    private int shadowRaysOf(LightSource light) {
        if (light.getPosition() == null || !light.isSoft()) return 1;
        int count = light.getNumSamples();
        return settings.adaptiveShadows() ? Math.min(count, probeCount(count)) : count;
    }

    private static int probeCount(int count) {
        return Math.max(5, (int) Math.round(Math.sqrt(count)));
    }

    /**
     * Fraction of {@code light} reaching the point, into {@code ctx.visibleR, G, B}: the transmittance of one
     * shadow ray, or averaged over a disk.
     */
    private void visibility(
            LightSource light, int li, SurfacePoint sp, LightSample ls, TraceContext ctx, long path, int[] occluders) {
        Point position = light.getPosition();
        if (position == null) {
            shadowToward(sp, -ls.lx, -ls.ly, -ls.lz, Double.POSITIVE_INFINITY, li, occluders, ctx);
            return;
        }
        if (!light.isSoft()) {
            shadowTo(sp, position.x, position.y, position.z, li, occluders, ctx);
            return;
        }
        // A disk of the light's radius facing the point, sampled by a beam of shadow rays.
        int count = light.getNumSamples();
        double diameter = 2 * light.getRadius();
        sp.basis(ls.lx, ls.ly, ls.lz);
        long seed = SampleStream.mix(SampleStream.mix(path, SHADOW), li);
        // In a batch of progressive samples (traceAgainBatch), the beam of each sample at once.
        int rays = count * ctx.sequenceBatch;
        double[] offsets = ctx.shadowOffsets(rays);
        if (settings.adaptiveShadows()) {
            // Probe the centre and a ring on the rim first: an occluder edge that crosses the disk almost surely
            // separates two of them, so agreement means the point is fully lit, in the umbra, or behind the same
            // glass from every part of the disk.
            int probes = probeCount(count);
            if (probes < count) {
                SuperSamplingBlackboard.getProbeOffsets(probes, ctx.random.reset(seed), offsets);
                diskVisibility(sp, position, diameter, probes, offsets, li, occluders, ctx);
                if (ctx.diskUniform) {
                    ctx.counters.samplesSaved += count - probes;
                    return;
                }
                seed = SampleStream.mix(seed, 1);
            }
        }
        if (!ctx.continueSequenceBatch(SHADOW, li, count, TargetShape.CIRCLE, offsets)) {
            // Outside a progressive render, where a batch is always one sample.
            SuperSamplingBlackboard.getSampleOffsets(
                    count, TargetShape.CIRCLE, settings.shadowPattern(), ctx.random.reset(seed), offsets);
        }
        diskVisibility(sp, position, diameter, rays, offsets, li, occluders, ctx);
    }

    /**
     * Mean transmittance of the shadow rays toward {@code count} points of the disk given by {@code offsets} (in
     * the point's {@link SurfacePoint#basis}). When every ray has the same transmittance (all clear, all blocked,
     * or all through the same glass) it is returned exactly, not as a sum divided by the count, so a soft light
     * that nothing partly hides shades exactly as the hard light; {@link TraceContext#diskUniform} tells whether
     * that was the case.
     */
    private void diskVisibility(
            SurfacePoint sp,
            Point c,
            double diameter,
            int count,
            double[] offsets,
            int li,
            int[] occluders,
            TraceContext ctx) {
        double r = 0, g = 0, b = 0;
        double firstR = 0, firstG = 0, firstB = 0;
        boolean uniform = true;
        // The rays share their path through the tree, with those of neighbouring points toward the same light: the
        // tree is searched once for them all (the answers are the same). The offsets lie within half the diameter of
        // the centre; the margin keeps rim points covered despite rounding.
        accelerator.aimShadowBeam(ctx.shadowHit, li, sp.px, sp.py, sp.pz, c.x, c.y, c.z, diameter * (0.5 + 0x1p-30));
        for (int i = 0; i < count; i++) {
            double a = offsets[2 * i] * diameter, bb = offsets[2 * i + 1] * diameter;
            double qx = c.x + a * sp.e1x + bb * sp.e2x;
            double qy = c.y + a * sp.e1y + bb * sp.e2y;
            double qz = c.z + a * sp.e1z + bb * sp.e2z;
            shadowTo(sp, qx, qy, qz, li, occluders, ctx);
            double tr = ctx.visibleR, tg = ctx.visibleG, tb = ctx.visibleB;
            if (i == 0) {
                firstR = tr;
                firstG = tg;
                firstB = tb;
            } else if (uniform && !(same(tr, firstR) && same(tg, firstG) && same(tb, firstB))) {
                uniform = false;
            }
            r += tr;
            g += tg;
            b += tb;
        }
        ctx.diskUniform = uniform;
        if (uniform) {
            ctx.visibleR = firstR;
            ctx.visibleG = firstG;
            ctx.visibleB = firstB;
        } else {
            ctx.visibleR = r / count;
            ctx.visibleG = g / count;
            ctx.visibleB = b / count;
        }
    }

    /** Equality as {@link Double3#equals} and {@link Color#equals} decide it. */
    private static boolean same(double a, double b) {
        return Double.compare(a, b) == 0;
    }

    /** Transmittance of the segment from the surface to the point (x, y, z), into {@code ctx.visibleR, G, B}. */
    private void shadowTo(SurfacePoint sp, double x, double y, double z, int li, int[] occluders, TraceContext ctx) {
        double dx = x - sp.px, dy = y - sp.py, dz = z - sp.pz;
        if (dx == 0 && dy == 0 && dz == 0) {
            ctx.visibleR = ctx.visibleG = ctx.visibleB = 1;
            return;
        }
        sp.spawn(dx, dy, dz);
        double ox = x - sp.originX, oy = y - sp.originY, oz = z - sp.originZ;
        if (ox == 0 && oy == 0 && oz == 0) {
            ctx.visibleR = ctx.visibleG = ctx.visibleB = 1;
            return;
        }
        ReusableRay ray = ctx.shadowRay.set(sp.originX, sp.originY, sp.originZ, ox, oy, oz);
        traceShadow(ray, Vector.length(ox, oy, oz), li, occluders, ctx);
    }

    /** Transmittance along a direction up to {@code tMax} (directional lights). */
    private void shadowToward(
            SurfacePoint sp, double dx, double dy, double dz, double tMax, int li, int[] occluders, TraceContext ctx) {
        sp.spawn(dx, dy, dz);
        ReusableRay ray = ctx.shadowRay.set(sp.originX, sp.originY, sp.originZ, dx, dy, dz);
        traceShadow(ray, tMax, li, occluders, ctx);
    }

    /** One shadow ray through (0, tMax), with the occluder cache of light {@code li}. */
    private void traceShadow(Ray ray, double tMax, int li, int[] occluders, TraceContext ctx) {
        ctx.counters.shadow++;
        HitRecord shadow = ctx.shadowHit;
        shadow.occluderHint = occluders[li];
        if (accelerator.passesLight(ray, 0, tMax, shadow)) {
            ctx.visibleR = shadow.transmitR;
            ctx.visibleG = shadow.transmitG;
            ctx.visibleB = shadow.transmitB;
            // Lit points come in runs as shadowed ones do: the next ray toward this light most likely passes too.
            occluders[li] = -1;
        } else {
            ctx.visibleR = ctx.visibleG = ctx.visibleB = 0;
            if (shadow.occluder >= 0) occluders[li] = shadow.occluder;
        }
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
