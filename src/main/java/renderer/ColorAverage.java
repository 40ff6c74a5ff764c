package renderer;

import primitives.Color;

/**
 * The mean of a beam of sample colours, reusable: {@link #reset} starts a new beam. When every sample is
 * bit-identical the mean is that colour exactly (a plain sum-then-divide can be an ulp off), so a beam of identical
 * rays gives the single-ray result.
 */
final class ColorAverage {
    private double r, g, b;
    private double firstR, firstG, firstB;
    private int count;
    private boolean allEqual = true;

    /** Forgets every sample. */
    ColorAverage reset() {
        r = g = b = 0;
        count = 0;
        allEqual = true;
        return this;
    }

    void add(Color c) {
        add(c.getR(), c.getG(), c.getB());
    }

    /** Adds the colour a trace left in {@code ctx}. */
    void add(TraceContext ctx) {
        add(ctx.red, ctx.green, ctx.blue);
    }

    void add(double red, double green, double blue) {
        if (count == 0) {
            firstR = red;
            firstG = green;
            firstB = blue;
        } else if (allEqual
                && !(Double.compare(red, firstR) == 0
                        && Double.compare(green, firstG) == 0
                        && Double.compare(blue, firstB) == 0)) {
            allEqual = false; // equality as Color.equals decides it
        }
        r += red;
        g += green;
        b += blue;
        count++;
    }

    int count() {
        return count;
    }

    /** The mean as a colour (black for no samples). */
    Color mean() {
        if (count == 0) return Color.BLACK;
        if (allEqual) return new Color(firstR, firstG, firstB);
        return new Color(r / count, g / count, b / count);
    }

    /** The mean into {@code ctx.red, green, blue}, allocating nothing. */
    void meanInto(TraceContext ctx) {
        if (count == 0) ctx.setColor(0, 0, 0);
        else if (allEqual) ctx.setColor(firstR, firstG, firstB);
        else ctx.setColor(r / count, g / count, b / count);
    }
}
