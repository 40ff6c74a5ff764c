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

    /** Jittered: one random sample in each cell of a grid. */
    public static final Variant JITTERED = new Variant(SamplingPattern.JITTERED, false);
    /** Random: independent uniform samples. */
    public static final Variant RANDOM = new Variant(SamplingPattern.RANDOM, false);
    /** Halton: a randomly shifted low-discrepancy sequence. */
    public static final Variant HALTON = new Variant(SamplingPattern.HALTON, false);

    /**
     * A short label for tables and chart legends.
     *
     * @return the pattern in lower case, preceded by "adaptive " when adaptive
     */
    public String label() {
        String name = pattern.name().toLowerCase(java.util.Locale.ROOT);
        return adaptive ? "adaptive " + name : name;
    }
}
