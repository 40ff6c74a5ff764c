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
        SamplingConfig glossySampling) {

    /** BVH on, planning on, 10 levels, cutoff 0.001, jittered shadows, 16 jittered glossy rays. */
    public static final RenderSettings DEFAULT = new RenderSettings(
            true,
            Accelerator.DEFAULT_BINS,
            Accelerator.DEFAULT_MAX_LEAF_SIZE,
            true,
            10,
            0.001,
            SamplingPattern.JITTERED,
            false,
            new SamplingConfig(16, TargetShape.CIRCLE, SamplingPattern.JITTERED));

    public RenderSettings {
        if (bvhBins < 2 || bvhBins > 256) {
            throw new IllegalArgumentException("bvhBins must be in [2, 256], but was " + bvhBins);
        }
        if (bvhMaxLeafSize < 1 || bvhMaxLeafSize > 64) {
            throw new IllegalArgumentException("bvhMaxLeafSize must be in [1, 64], but was " + bvhMaxLeafSize);
        }
        if (maxLevel < 1) {
            throw new IllegalArgumentException("maxLevel must be >= 1, but was " + maxLevel);
        }
        if (!(minAttenuation >= 0 && minAttenuation < 1)) {
            throw new IllegalArgumentException("minAttenuation must be in [0, 1), but was " + minAttenuation);
        }
        if (shadowPattern == null) throw new IllegalArgumentException("shadowPattern must not be null");
        if (glossySampling == null) throw new IllegalArgumentException("glossySampling must not be null");
    }

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
                glossySampling);
    }

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
                glossySampling);
    }

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
                glossySampling);
    }

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
                glossySampling);
    }

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
                glossySampling);
    }

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
                glossy);
    }
}
