package lighting;

/**
 * What one light gives one shading point, filled by {@link LightSource#illuminate} without allocating: the
 * renderer keeps one per thread and reuses it for every light and every point.
 */
public final class LightSample {
    /**
     * Distance from the light to the point: infinite for directional lights, 0 when the point is the light itself
     * (then nothing else is set).
     */
    public double distance;

    /** The unit direction from the light toward the point. */
    public double lx, ly, lz;

    /** The intensity arriving at the point, attenuation and beam shape included (0 where the light cannot reach). */
    public double r, g, b;

    /**
     * Whether no light arrives (every channel exactly 0).
     *
     * @return true when the red, green and blue intensities are all 0
     */
    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }
}
