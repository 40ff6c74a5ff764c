package renderer;

import geometries.Accelerator;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/**
 * The knobs of a render that are not part of the scene: acceleration (BVH on/off and its build parameters),
 * effect planning, recursion limits and how soft shadows and glossy rays are sampled. Immutable; the
 * {@code with...} methods return modified copies.
 *
 * @param useBvh search with the BVH (true) or by brute force over the same flat arrays (false)
 * @param bvhBins SAH bins per node
 * @param bvhMaxLeafSize most primitives per leaf
 * @param planEffects skip work whose contribution is provably zero (false fires it anyway, for verification)
 * @param maxLevel deepest recursion of reflection and refraction (1 = no secondary rays)
 * @param minAttenuation recursion stops when the accumulated attenuation falls below this in every channel
 * @param shadowPattern placement of shadow rays on a light's disk
 * @param adaptiveShadows probe a few shadow rays first and fire the rest only where the probes disagree
 * @param glossySampling rays per glossy reflection or frosted refraction (shape is always a cone: CIRCLE)
 * @param lightCutoff the most direct light, in display steps (the 0..255 scale of a channel), that one camera
 *     sample may leave out by not sampling lights too faint to matter where they are (no shadow rays toward them);
 *     0 is exact. The default 0.5 can change a channel of the 8-bit image by at most one step, and only where its
 *     exact value lies within half a step of a rounding boundary (docs/BENCHMARKS.md, "Lights that cannot matter")
 */
public record RenderSettings(
        boolean useBvh,
        int bvhBins,
        int bvhMaxLeafSize,
        boolean planEffects,
        int maxLevel,
        double minAttenuation,
        SamplingPattern shadowPattern,
        boolean adaptiveShadows,
        SamplingConfig glossySampling,
        double lightCutoff) {

    /**
     * Deepest recursion allowed: far beyond what any image needs (each level is a bounce; paths fade long before),
     * and shallow enough that two perfect mirrors facing each other cannot overflow a render thread's stack.
     */
    public static final int MAX_LEVEL = 256;

    /**
     * BVH on, planning on, 10 levels, recursion cut below attenuation 0.001, jittered shadows, 16 jittered glossy
     * rays, light cut-off half a display step.
     */
    public static final RenderSettings DEFAULT = new RenderSettings(
            true,
            Accelerator.DEFAULT_BINS,
            Accelerator.DEFAULT_MAX_LEAF_SIZE,
            true,
            10,
            0.001,
            SamplingPattern.JITTERED,
            false,
            new SamplingConfig(16, TargetShape.CIRCLE, SamplingPattern.JITTERED),
            0.5);

    /**
     * Checks every setting.
     *
     * @param useBvh search with the BVH (true) or by brute force (false)
     * @param bvhBins SAH bins per node, 2..256
     * @param bvhMaxLeafSize most primitives per leaf, 1..64
     * @param planEffects skip work whose contribution is provably zero
     * @param maxLevel deepest recursion of reflection and refraction, 1 to {@link #MAX_LEVEL}
     * @param minAttenuation the attenuation below which recursion stops, in [0, 1)
     * @param shadowPattern placement of shadow rays on a light's disk; not null
     * @param adaptiveShadows probe a few shadow rays first and fire the rest only where they disagree
     * @param glossySampling rays per glossy reflection or frosted refraction; not null
     * @param lightCutoff display steps of direct light a camera sample may leave out, in [0, 255]
     * @throws IllegalArgumentException if a setting is out of range or null
     */
    public RenderSettings {
        if (bvhBins < 2 || bvhBins > 256) {
            throw new IllegalArgumentException("bvhBins must be in [2, 256], but was " + bvhBins);
        }
        if (bvhMaxLeafSize < 1 || bvhMaxLeafSize > 64) {
            throw new IllegalArgumentException("bvhMaxLeafSize must be in [1, 64], but was " + bvhMaxLeafSize);
        }
        if (maxLevel < 1 || maxLevel > MAX_LEVEL) {
            throw new IllegalArgumentException("maxLevel must be in [1, " + MAX_LEVEL + "], but was " + maxLevel);
        }
        if (!(minAttenuation >= 0 && minAttenuation < 1)) {
            throw new IllegalArgumentException("minAttenuation must be in [0, 1), but was " + minAttenuation);
        }
        if (shadowPattern == null) throw new IllegalArgumentException("shadowPattern must not be null");
        if (glossySampling == null) throw new IllegalArgumentException("glossySampling must not be null");
        if (!(lightCutoff >= 0 && lightCutoff <= 255)) {
            throw new IllegalArgumentException("lightCutoff must be in [0, 255] display steps, but was " + lightCutoff);
        }
    }

    /**
     * These settings with the BVH turned on or off.
     *
     * @param on true to search with the BVH, false for brute force
     * @return a modified copy
     */
    public RenderSettings withBvh(boolean on) {
        return new RenderSettings(
                on,
                bvhBins,
                bvhMaxLeafSize,
                planEffects,
                maxLevel,
                minAttenuation,
                shadowPattern,
                adaptiveShadows,
                glossySampling,
                lightCutoff);
    }

    /**
     * These settings with other BVH build parameters.
     *
     * @param bins SAH bins per node, 2..256
     * @param maxLeafSize most primitives per leaf, 1..64
     * @return a modified copy
     * @throws IllegalArgumentException if a parameter is out of range
     */
    public RenderSettings withBvhBuild(int bins, int maxLeafSize) {
        return new RenderSettings(
                useBvh,
                bins,
                maxLeafSize,
                planEffects,
                maxLevel,
                minAttenuation,
                shadowPattern,
                adaptiveShadows,
                glossySampling,
                lightCutoff);
    }

    /**
     * These settings with effect planning turned on or off.
     *
     * @param on true to skip work that cannot change the image, false to fire it anyway
     * @return a modified copy
     */
    public RenderSettings withPlanEffects(boolean on) {
        return new RenderSettings(
                useBvh,
                bvhBins,
                bvhMaxLeafSize,
                on,
                maxLevel,
                minAttenuation,
                shadowPattern,
                adaptiveShadows,
                glossySampling,
                lightCutoff);
    }

    /**
     * These settings with other recursion limits.
     *
     * @param maxLevel deepest recursion of reflection and refraction, 1 to {@link #MAX_LEVEL}
     * @param minAttenuation the attenuation below which recursion stops, in [0, 1)
     * @return a modified copy
     * @throws IllegalArgumentException if a limit is out of range
     */
    public RenderSettings withRecursion(int maxLevel, double minAttenuation) {
        return new RenderSettings(
                useBvh,
                bvhBins,
                bvhMaxLeafSize,
                planEffects,
                maxLevel,
                minAttenuation,
                shadowPattern,
                adaptiveShadows,
                glossySampling,
                lightCutoff);
    }

    /**
     * These settings with another sampling of soft shadows.
     *
     * @param pattern placement of shadow rays on a light's disk; not null
     * @param adaptive true to probe a few shadow rays first and fire the rest only where they disagree
     * @return a modified copy
     */
    public RenderSettings withShadowSampling(SamplingPattern pattern, boolean adaptive) {
        return new RenderSettings(
                useBvh,
                bvhBins,
                bvhMaxLeafSize,
                planEffects,
                maxLevel,
                minAttenuation,
                pattern,
                adaptive,
                glossySampling,
                lightCutoff);
    }

    /**
     * These settings with another sampling of glossy reflection and frosted refraction.
     *
     * @param glossy the rays per rough bounce and their pattern; not null
     * @return a modified copy
     */
    public RenderSettings withGlossySampling(SamplingConfig glossy) {
        return new RenderSettings(
                useBvh,
                bvhBins,
                bvhMaxLeafSize,
                planEffects,
                maxLevel,
                minAttenuation,
                shadowPattern,
                adaptiveShadows,
                glossy,
                lightCutoff);
    }

    /**
     * The light cut-off in display steps (0 = exact); see the class description.
     *
     * @param displaySteps the cut-off in display steps, in [0, 255]
     * @return a modified copy
     * @throws IllegalArgumentException if {@code displaySteps} is outside [0, 255]
     */
    public RenderSettings withLightCutoff(double displaySteps) {
        return new RenderSettings(
                useBvh,
                bvhBins,
                bvhMaxLeafSize,
                planEffects,
                maxLevel,
                minAttenuation,
                shadowPattern,
                adaptiveShadows,
                glossySampling,
                displaySteps);
    }
}
