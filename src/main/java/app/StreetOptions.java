package app;

/**
 * The knobs of the {@link StreetScene} that change what is rendered rather than how: the radius and shadow-ray
 * count of every lamp (street lamps and the shelter's spot). A radius of 0 or one sample gives hard shadows.
 *
 * @param lampRadius radius of each lamp's emitting disk, in scene units (1 = 5 cm)
 * @param lampSamples shadow rays per shading point and lamp when the radius is positive
 */
public record StreetOptions(double lampRadius, int lampSamples) {
    /** Point lamps: hard shadows. */
    public static final StreetOptions HARD = new StreetOptions(0, 1);

    /**
     * Checks the lamp settings.
     *
     * @param lampRadius the radius of the lamps' disks, finite and at least 0 (0: point lamps)
     * @param lampSamples shadow rays per lamp, at least 1
     * @throws IllegalArgumentException if {@code lampRadius} is negative or not finite, or {@code lampSamples} is below
     *     1
     */
    public StreetOptions {
        if (!(lampRadius >= 0) || !Double.isFinite(lampRadius)) {
            throw new IllegalArgumentException("lampRadius must be finite and >= 0, but was " + lampRadius);
        }
        if (lampSamples < 1) throw new IllegalArgumentException("lampSamples must be >= 1, but was " + lampSamples);
    }

    /**
     * Disk lamps of the given radius sampled by {@code samples} shadow rays each: soft shadows.
     *
     * @param radius the disk radius in scene units
     * @param samples shadow rays per lamp and shading point
     * @return the options
     */
    public static StreetOptions soft(double radius, int samples) {
        return new StreetOptions(radius, samples);
    }

    /**
     * Whether the lamps cast soft shadows.
     *
     * @return true when the radius is positive and more than one sample is taken
     */
    public boolean softShadows() {
        return lampRadius > 0 && lampSamples > 1;
    }
}
