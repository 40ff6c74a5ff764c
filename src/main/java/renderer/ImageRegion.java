package renderer;

import java.io.Serializable;
import primitives.Color;

/**
 * The linear floating-point pixels of a rectangle of an image, as {@link Camera#renderRegion} renders them:
 * columns {@code x0 .. x0 + width - 1}, rows {@code y0 .. y0 + height - 1}, addressed in the coordinates of the
 * whole image. {@link ImageWriter#writeRegion} copies it into an image.
 *
 * <p>Serializable because regions are what a distributed render sends back from its workers (the pixels are one
 * {@code double[]}, which Java serialization writes in bulk). Only the renderer writes its pixels.
 */
public final class ImageRegion implements Serializable {
    private static final long serialVersionUID = 1L;

    /** The leftmost column and top row (image coordinates) and the size in pixels. */
    private final int x0, y0, width, height;
    /** Red, green and blue of each pixel, row by row. */
    private final double[] pixels;

    /** An all-black region, checked to lie inside an image of {@code nX} x {@code nY} pixels. */
    ImageRegion(int x0, int y0, int width, int height, int nX, int nY) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("region must not be empty, but was " + width + " x " + height);
        }
        if (x0 < 0 || y0 < 0 || x0 > nX - width || y0 > nY - height) {
            throw new IllegalArgumentException("region of " + width + " x " + height + " at (" + x0 + ", " + y0
                    + ") is not inside the " + nX + " x " + nY + " image");
        }
        this.x0 = x0;
        this.y0 = y0;
        this.width = width;
        this.height = height;
        this.pixels = new double[3 * width * height];
    }

    /**
     * Leftmost column, in image coordinates.
     *
     * @return the 0-based column of the region's left edge
     */
    public int getX0() {
        return x0;
    }

    /**
     * Top row, in image coordinates.
     *
     * @return the 0-based row of the region's top edge
     */
    public int getY0() {
        return y0;
    }

    /**
     * The number of columns.
     *
     * @return the width in pixels, at least 1
     */
    public int getWidth() {
        return width;
    }

    /**
     * The number of rows.
     *
     * @return the height in pixels, at least 1
     */
    public int getHeight() {
        return height;
    }

    /** Sets pixel (x, y) of the image, which must lie in this region. */
    void writePixel(int x, int y, double red, double green, double blue) {
        int o = offset(x, y);
        if (Double.isNaN(red) || Double.isNaN(green) || Double.isNaN(blue)) {
            throw new IllegalArgumentException(
                    "pixel (" + x + ", " + y + ") colour is NaN: rgb(" + red + "," + green + "," + blue + ")");
        }
        pixels[o] = red;
        pixels[o + 1] = green;
        pixels[o + 2] = blue;
    }

    /**
     * The linear colour of pixel (x, y) of the image, which must lie in this region.
     *
     * @param x the 0-based column in the image
     * @param y the 0-based row in the image
     * @return a new colour of the pixel's unclamped channels
     */
    public Color getPixel(int x, int y) {
        int o = offset(x, y);
        return new Color(pixels[o], pixels[o + 1], pixels[o + 2]);
    }

    /** Copies row {@code y} of the region (3 doubles per pixel) into {@code target} at {@code at}. */
    void copyRow(int y, double[] target, int at) {
        System.arraycopy(pixels, offset(x0, y), target, at, 3 * width);
    }

    private int offset(int x, int y) {
        if (x < x0 || x >= x0 + width || y < y0 || y >= y0 + height) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is outside the region of " + width + " x "
                    + height + " at (" + x0 + ", " + y0 + ")");
        }
        return 3 * ((y - y0) * width + (x - x0));
    }
}
