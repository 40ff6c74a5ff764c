package report;

import renderer.sampling.SamplingPattern;

/**
 * One way of spending samples on an effect: a pattern, fixed or adaptive.
 *
 * @param pattern where the samples go
 * @param adaptive whether the count is a maximum, refined only where samples disagree
 */
public record Variant(SamplingPattern pattern, boolean adaptive) {
    /** The four fixed patterns. */
    public static final Variant GRID = new Variant(SamplingPattern.GRID, false);

    public static final Variant JITTERED = new Variant(SamplingPattern.JITTERED, false);
    public static final Variant RANDOM = new Variant(SamplingPattern.RANDOM, false);
    public static final Variant HALTON = new Variant(SamplingPattern.HALTON, false);

    /** A short label for tables and chart legends. */
    public String label() {
        String name = pattern.name().toLowerCase(java.util.Locale.ROOT);
        return adaptive ? "adaptive " + name : name;
    }
}
