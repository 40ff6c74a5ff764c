package renderer.sampling;

import java.util.Objects;
import primitives.Limits;

/**
 * How many samples to take over which target shape with which pattern, e.g.
 * {@code new SamplingConfig(81, RECTANGLE, GRID)}. A count of 1 means one ray through the centre (the feature is
 * off). For anti-aliasing, {@link #adaptive(double)} makes the count an upper bound: a pixel is subdivided only
 * where sample colours differ by more than the threshold.
 */
public final class SamplingConfig {
    /** One central sample: the feature is off. */
    public static final SamplingConfig NONE = new SamplingConfig(1, TargetShape.RECTANGLE, SamplingPattern.GRID);

    private final int sampleCount;
    private final TargetShape shape;
    private final SamplingPattern pattern;
    private final double adaptiveThreshold;

    /**
     * A non-adaptive configuration.
     *
     * @param sampleCount the number of samples, 1 (off: one central sample) to {@link primitives.Limits#MAX_SAMPLES}
     * @param shape the area sampled: square or disk; not null
     * @param pattern how the samples are placed in the area; not null
     * @throws IllegalArgumentException if {@code sampleCount} is out of range
     */
    public SamplingConfig(int sampleCount, TargetShape shape, SamplingPattern pattern) {
        this(sampleCount, shape, pattern, 0);
    }

    private SamplingConfig(int sampleCount, TargetShape shape, SamplingPattern pattern, double adaptiveThreshold) {
        if (sampleCount < 1 || sampleCount > Limits.MAX_SAMPLES) {
            throw new IllegalArgumentException(
                    "sampleCount must be in [1, " + Limits.MAX_SAMPLES + "], but was " + sampleCount);
        }
        this.sampleCount = sampleCount;
        this.shape = Objects.requireNonNull(shape, "shape must not be null");
        this.pattern = Objects.requireNonNull(pattern, "pattern must not be null");
        this.adaptiveThreshold = adaptiveThreshold;
    }

    /**
     * This configuration made adaptive: sample colours (0..255 scale) that differ by more than
     * {@code threshold} in any channel trigger refinement; {@link #getSampleCount()} becomes the maximum.
     *
     * @param threshold the colour difference (0..255 scale) above which a pixel is refined; positive and finite
     * @return a new adaptive configuration with the same count, shape and pattern
     * @throws IllegalArgumentException if {@code threshold} is not positive and finite
     */
    public SamplingConfig adaptive(double threshold) {
        if (!(threshold > 0) || !Double.isFinite(threshold)) {
            throw new IllegalArgumentException("adaptive threshold must be positive and finite, but was " + threshold);
        }
        return new SamplingConfig(sampleCount, shape, pattern, threshold);
    }

    /**
     * The number of samples; the maximum when adaptive.
     *
     * @return the sample count, at least 1
     */
    public int getSampleCount() {
        return sampleCount;
    }

    /**
     * The shape of the sampled area.
     *
     * @return the target shape, never null
     */
    public TargetShape getShape() {
        return shape;
    }

    /**
     * The placement of the samples.
     *
     * @return the sampling pattern, never null
     */
    public SamplingPattern getPattern() {
        return pattern;
    }

    /**
     * Whether the count is an upper bound and refinement is driven by colour differences.
     *
     * @return true when an adaptive threshold was set
     */
    public boolean isAdaptive() {
        return adaptiveThreshold > 0;
    }

    /**
     * Colour difference that triggers refinement; 0 when not adaptive.
     *
     * @return the adaptive threshold on the 0..255 scale, or 0
     */
    public double getAdaptiveThreshold() {
        return adaptiveThreshold;
    }

    /**
     * Whether this configuration takes more than one sample.
     *
     * @return true when the sample count is above 1
     */
    public boolean isEnabled() {
        return sampleCount > 1;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof SamplingConfig c
                && c.sampleCount == sampleCount
                && c.shape == shape
                && c.pattern == pattern
                && c.adaptiveThreshold == adaptiveThreshold;
    }

    @Override
    public int hashCode() {
        return Objects.hash(sampleCount, shape, pattern, adaptiveThreshold);
    }

    @Override
    public String toString() {
        return sampleCount + " " + pattern + " over " + shape
                + (isAdaptive() ? " adaptive(" + adaptiveThreshold + ")" : "");
    }
}
