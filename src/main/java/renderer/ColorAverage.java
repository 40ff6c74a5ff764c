package renderer;

import primitives.Color;

/**
 * The mean of a beam of sample colours. When every sample is bit-identical the mean is that colour exactly
 * (a plain sum-then-divide can be an ulp off), so a beam of identical rays gives the single-ray result.
 */
final class ColorAverage {
    private double r, g, b;
    private int count;
    private Color first;
    private boolean allEqual = true;

    void add(Color c) {
        if (count == 0) {
            first = c;
        } else if (allEqual && !c.equals(first)) {
            allEqual = false;
        }
        r += c.getR();
        g += c.getG();
        b += c.getB();
        count++;
    }

    int count() {
        return count;
    }

    Color mean() {
        if (count == 0) return Color.BLACK;
        if (allEqual) return first;
        return new Color(r / count, g / count, b / count);
    }
}
