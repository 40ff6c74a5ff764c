package primitives;

/**
 * A linear RGB colour with channels in doubles on the course scale (255 = full intensity of an 8-bit channel).
 * Values are never clamped during rendering; {@code ImageWriter} clamps once, when the image is written.
 */
public final class Color {
    public static final Color BLACK = new Color(0, 0, 0);

    private final Double3 rgb;

    public Color(double r, double g, double b) {
        this.rgb = new Double3(r, g, b);
    }

    private Color(Double3 rgb) {
        this.rgb = rgb;
    }

    /** The colour of an AWT colour, channels 0..255. */
    public Color(java.awt.Color color) {
        this(color.getRed(), color.getGreen(), color.getBlue());
    }

    public double getR() {
        return rgb.d1;
    }

    public double getG() {
        return rgb.d2;
    }

    public double getB() {
        return rgb.d3;
    }

    /** The channels as a triple. */
    public Double3 toDouble3() {
        return rgb;
    }

    public Color add(Color other) {
        return new Color(rgb.add(other.rgb));
    }

    /** The sum of this colour and several others. */
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

    public Color scale(double factor) {
        return new Color(rgb.scale(factor));
    }

    /** Per-channel scaling (attenuation by a material coefficient). */
    public Color scale(Double3 factors) {
        return new Color(rgb.product(factors));
    }

    public Color reduce(double divisor) {
        return new Color(rgb.reduce(divisor));
    }

    /** Whether every channel is exactly zero. */
    public boolean isBlack() {
        return rgb.isZero();
    }

    /** Whether every channel is a finite number. */
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
