package renderer;

import geometries.Accelerator;
import geometries.HitRecord;
import geometries.ShadowPacket;
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
import renderer.sampling.SuperSamplingBlackboard;
import renderer.sampling.TargetShape;

/**
 * The direct light at a shading point, for {@link SimpleRayTracer}: each light's unshadowed contribution through the
 * Phong response ({@code kD |n.l| + kS max(0, -v.r)^shininess}), the light cut-off that sets the faintest aside, and
 * the visibility of the others by shadow rays: one toward a point or directional light, a beam over the disk of a
 * light with a radius (soft shadows, optionally adaptive), in a progressive render continuing the pixel half's
 * sequence, for a batch of samples at once. Shadow rays start at {@link SurfacePoint#spawn} and leave out the flat
 * surface they start on. Allocation-free: its scratch is the thread's {@link TraceContext}.
 */
final class DirectLightEstimator {
    /** The stream of shadow beams' random offsets (mixed with the path and the light). */
    private static final long SHADOW = 3;

    private final LightSource[] lights;
    private final EffectPlan plan;
    private final RenderSettings settings;
    private final Accelerator accelerator;

    DirectLightEstimator(LightSource[] lights, EffectPlan plan, RenderSettings settings, Accelerator accelerator) {
        this.lights = lights;
        this.plan = plan;
        this.settings = settings;
        this.accelerator = accelerator;
    }

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
     *
     * <p>With {@code firstHit} (the primary ray's hit, shaded at the first level) the unshadowed terms and the cut-off's
     * choice are kept, and the samples that shade the same hit again ({@link SimpleRayTracer#traceAgain}: progressive
     * samples through a pinhole's pixel centre) take them as they are: they depend on the point, its material, the
     * view and the lights, which those samples share, and on the cut-off's budget, which each sample starts afresh.
     * Only the shadow rays differ. The colours are the same bit for bit.
     */
    void estimate(
            SurfacePoint sp,
            Material m,
            double vx,
            double vy,
            double vz,
            double nv,
            TraceContext ctx,
            long path,
            double weight,
            boolean firstHit) {
        DirectLighting direct = ctx.direct(lights.length);
        if (firstHit && ctx.termsKept) {
            ctx.cutoffBudget = ctx.termsCutoffLeft;
        } else {
            ctx.termsKept = false; // the terms are about to be another point's
            // Every light's unshadowed contribution, then, with the light cut-off, the faintest set aside (which
            // spends the sample's budget).
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
                direct.set(
                        li, contributes ? DirectLighting.CONTRIBUTES : DirectLighting.WEIGHTLESS, fr, fg, fb, weight);
            }
            if (plan.lightCutoff > 0) {
                ctx.cutoffBudget = direct.setAsideFaintest(ctx.cutoffBudget);
            }
            if (firstHit) {
                ctx.termsKept = true;
                ctx.termsCutoffLeft = ctx.cutoffBudget;
            }
        }
        shadowedSum(sp, ctx, path, direct);
    }

    /**
     * The lights of {@code direct} not skipped or set aside, each through its shadow rays, then those set aside in the
     * proportion the others passed, into {@code ctx.red, green, blue}.
     */
    private void shadowedSum(SurfacePoint sp, TraceContext ctx, long path, DirectLighting direct) {
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

    /** Whether a light's shadow is one ray per shading point: a directional light, or a point without a disk. */
    static boolean castsOneShadowRay(LightSource light) {
        return light.getPosition() == null || !light.isSoft();
    }

    /** The fewest shadow rays a light costs per shading point: one, a disk's count, or its adaptive probes. */
    private int shadowRaysOf(LightSource light) {
        if (castsOneShadowRay(light)) return 1;
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
        if (count > 1 && accelerator.testsShadowPackets()) {
            packetVisibility(sp, c, diameter, count, offsets, ctx);
            return;
        }
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

    /**
     * {@link #diskVisibility} where every surface is opaque and no tree is searched: the rays in one packet, each
     * primitive tested against all of them ({@link Accelerator#blockShadowPacket}). Each ray passes whole or not at
     * all, so the sums and the uniform case come out as the rays one by one give them.
     */
    private void packetVisibility(
            SurfacePoint sp, Point c, double diameter, int count, double[] offsets, TraceContext ctx) {
        ShadowPacket packet = ctx.shadowPacket;
        packet.clear();
        int passed = 0; // segments with nothing to trace: lit, as in shadowTo
        for (int i = 0; i < count; i++) {
            double a = offsets[2 * i] * diameter, bb = offsets[2 * i + 1] * diameter;
            double qx = c.x + a * sp.e1x + bb * sp.e2x;
            double qy = c.y + a * sp.e1y + bb * sp.e2y;
            double qz = c.z + a * sp.e1z + bb * sp.e2z;
            if (!aim(sp, qx, qy, qz)) {
                passed++;
                continue;
            }
            double ox = qx - sp.originX, oy = qy - sp.originY, oz = qz - sp.originZ;
            packet.add(sp.originX, sp.originY, sp.originZ, ox, oy, oz, Vector.length(ox, oy, oz));
        }
        ctx.counters.shadow += packet.size();
        accelerator.blockShadowPacket(packet, ctx.shadowHit);
        passed += packet.open();
        ctx.diskUniform = passed == 0 || passed == count;
        double visible = passed == count ? 1 : passed / (double) count;
        ctx.visibleR = ctx.visibleG = ctx.visibleB = visible;
    }

    /** Equality as {@link Double3#equals} and {@link Color#equals} decide it. */
    private static boolean same(double a, double b) {
        return Double.compare(a, b) == 0;
    }

    /** Transmittance of the segment from the surface to the point (x, y, z), into {@code ctx.visibleR, G, B}. */
    private void shadowTo(SurfacePoint sp, double x, double y, double z, int li, int[] occluders, TraceContext ctx) {
        if (!aim(sp, x, y, z)) {
            ctx.visibleR = ctx.visibleG = ctx.visibleB = 1;
            return;
        }
        double ox = x - sp.originX, oy = y - sp.originY, oz = z - sp.originZ;
        ReusableRay ray = ctx.shadowRay.set(sp.originX, sp.originY, sp.originZ, ox, oy, oz);
        traceShadow(ray, Vector.length(ox, oy, oz), li, occluders, ctx);
    }

    /**
     * Sets the origin of a shadow segment from the surface point toward (x, y, z), offset off the surface, into
     * {@code sp.originX, Y, Z}; false when there is no segment to trace (the point is the surface point, or its offset
     * origin), which counts as lit.
     */
    private static boolean aim(SurfacePoint sp, double x, double y, double z) {
        double dx = x - sp.px, dy = y - sp.py, dz = z - sp.pz;
        if (dx == 0 && dy == 0 && dz == 0) return false;
        sp.spawn(dx, dy, dz);
        double ox = x - sp.originX, oy = y - sp.originY, oz = z - sp.originZ;
        return !(ox == 0 && oy == 0 && oz == 0);
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
}
