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
     */
    public SamplingConfig adaptive(double threshold) {
        if (!(threshold > 0) || !Double.isFinite(threshold)) {
            throw new IllegalArgumentException("adaptive threshold must be positive and finite, but was " + threshold);
        }
        return new SamplingConfig(sampleCount, shape, pattern, threshold);
    }

    public int getSampleCount() {
        return sampleCount;
    }

    public TargetShape getShape() {
        return shape;
    }

    public SamplingPattern getPattern() {
        return pattern;
    }

    /** Whether the count is an upper bound and refinement is driven by colour differences. */
    public boolean isAdaptive() {
        return adaptiveThreshold > 0;
    }

    /** Colour difference that triggers refinement; 0 when not adaptive. */
    public double getAdaptiveThreshold() {
        return adaptiveThreshold;
    }

    /** Whether this configuration takes more than one sample. */
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
