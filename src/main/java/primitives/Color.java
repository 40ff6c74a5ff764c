package primitives;

/**
 * A linear RGB colour with channels in doubles on the course scale (255 = full intensity of an 8-bit channel).
 * Values are never clamped during rendering; {@code ImageWriter} clamps once, when the image is written.
 */
public final class Color {
    /** Black: no light, (0, 0, 0). */
    public static final Color BLACK = new Color(0, 0, 0);

    private final Double3 rgb;

    /**
     * A colour of the given channels.
     *
     * @param r red, on the 0..255 scale (not clamped)
     * @param g green, on the 0..255 scale (not clamped)
     * @param b blue, on the 0..255 scale (not clamped)
     */
    public Color(double r, double g, double b) {
        this.rgb = new Double3(r, g, b);
    }

    private Color(Double3 rgb) {
        this.rgb = rgb;
    }

    /**
     * The colour of an AWT colour, channels 0..255.
     *
     * @param color the AWT colour; not null
     */
    public Color(java.awt.Color color) {
        this(color.getRed(), color.getGreen(), color.getBlue());
    }

    /**
     * The red channel.
     *
     * @return red, on the 0..255 scale, not clamped
     */
    public double getR() {
        return rgb.d1;
    }

    /**
     * The green channel.
     *
     * @return green, on the 0..255 scale, not clamped
     */
    public double getG() {
        return rgb.d2;
    }

    /**
     * The blue channel.
     *
     * @return blue, on the 0..255 scale, not clamped
     */
    public double getB() {
        return rgb.d3;
    }

    /**
     * The channels as a triple.
     *
     * @return the red, green and blue channels as {@code d1}, {@code d2}, {@code d3}
     */
    public Double3 toDouble3() {
        return rgb;
    }

    /**
     * The channel-wise sum of two colours.
     *
     * @param other the colour added
     * @return a new colour
     */
    public Color add(Color other) {
        return new Color(rgb.add(other.rgb));
    }

    /**
     * The sum of this colour and several others.
     *
     * @param others the colours added
     * @return a new colour
     */
    public Color add(Color... others) {
        double r = rgb.d1;
        double g = rgb.d2;
        double b = rgb.d3;
        for (Color c : others) {
            r += c.rgb.d1;
            g += c.rgb.d2;
            b += c.rgb.d3;
        }
        return new Color(r, g, b);
    }

    /**
     * This colour scaled by one factor in every channel.
     *
     * @param factor the factor
     * @return a new colour
     */
    public Color scale(double factor) {
        return new Color(rgb.scale(factor));
    }

    /**
     * Per-channel scaling (attenuation by a material coefficient).
     *
     * @param factors the factor of each channel
     * @return a new colour
     */
    public Color scale(Double3 factors) {
        return new Color(rgb.product(factors));
    }

    /**
     * This colour divided by one divisor in every channel.
     *
     * @param divisor the divisor, non-zero for a finite result
     * @return a new colour
     */
    public Color reduce(double divisor) {
        return new Color(rgb.reduce(divisor));
    }

    /**
     * Whether every channel is exactly zero.
     *
     * @return true when red, green and blue are all 0
     */
    public boolean isBlack() {
        return rgb.isZero();
    }

    /**
     * Whether every channel is a finite number.
     *
     * @return true when no channel is NaN or infinite
     */
    public boolean isFinite() {
        return Double.isFinite(rgb.d1) && Double.isFinite(rgb.d2) && Double.isFinite(rgb.d3);
    }

    @Override
    public boolean equals(Object obj) {
        return obj instanceof Color other && rgb.equals(other.rgb);
    }

    @Override
    public int hashCode() {
        return rgb.hashCode();
    }

    @Override
    public String toString() {
        return "rgb" + rgb;
    }
}
