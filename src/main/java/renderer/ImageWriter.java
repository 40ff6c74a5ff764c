package renderer;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import primitives.Color;
import primitives.Limits;

/**
 * An image of linear floating-point pixels that is written once, as PNG, with each channel clamped to 0..255
 * only then. Writing goes to a temporary file in the target folder which is then moved into place, so an error
 * or a crash never leaves a truncated or half-written image.
 */
public class ImageWriter {
    /** The folder images go to by default, relative to the working directory. */
    public static final Path DEFAULT_FOLDER = Path.of("images");

    private final String imageName;
    private final int nX;
    private final int nY;
    private final double[] pixels;

    /**
     * @param imageName file name without extension; may contain sub-folders, not ".."
     * @param nX the image width in pixels, at least 1
     * @param nY the image height in pixels, at least 1, with {@code nX * nY} at most 2^28
     * @throws IllegalArgumentException if the name is invalid or the resolution is not positive or too large
     */
    public ImageWriter(String imageName, int nX, int nY) {
        this.imageName = validateName(imageName);
        if (nX < 1 || nY < 1) {
            throw new IllegalArgumentException("image resolution must be positive, but was " + nX + " x " + nY);
        }
        if ((long) nX * nY > Limits.MAX_PIXELS) {
            throw new IllegalArgumentException(
                    "image of " + nX + " x " + nY + " pixels is too large (limit 2^28 pixels)");
        }
        this.nX = nX;
        this.nY = nY;
        this.pixels = new double[3 * nX * nY];
    }

    private static String validateName(String name) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("image name must not be empty");
        }
        Path path = Path.of(name);
        if (path.isAbsolute() || name.contains("..")) {
            throw new IllegalArgumentException(
                    "image name must be a relative name without '..', but was '" + name + "'");
        }
        return name;
    }

    /**
     * The image's name: its file name without extension.
     *
     * @return the name, possibly with sub-folders
     */
    public String getImageName() {
        return imageName;
    }

    /**
     * The image width.
     *
     * @return the number of columns
     */
    public int getNx() {
        return nX;
    }

    /**
     * The image height.
     *
     * @return the number of rows
     */
    public int getNy() {
        return nY;
    }

    /**
     * Sets pixel (x, y), x to the right and y downward from the top-left corner.
     *
     * @param xIndex the 0-based column
     * @param yIndex the 0-based row
     * @param color the linear colour; not NaN
     */
    public void writePixel(int xIndex, int yIndex, Color color) {
        writePixel(xIndex, yIndex, color.getR(), color.getG(), color.getB());
    }

    /**
     * Sets pixel (x, y) to the linear colour (red, green, blue).
     *
     * @param xIndex the 0-based column
     * @param yIndex the 0-based row
     * @param red the red channel on the 0..255 scale, not NaN (not clamped)
     * @param green the green channel on the 0..255 scale, not NaN (not clamped)
     * @param blue the blue channel on the 0..255 scale, not NaN (not clamped)
     * @throws IllegalArgumentException if the pixel is outside the image or a channel is NaN
     */
    public void writePixel(int xIndex, int yIndex, double red, double green, double blue) {
        checkIndex(xIndex, yIndex);
        if (Double.isNaN(red) || Double.isNaN(green) || Double.isNaN(blue)) {
            throw new IllegalArgumentException("pixel (" + xIndex + ", " + yIndex + ") colour is NaN: rgb(" + red + ","
                    + green + "," + blue + ")");
        }
        int o = 3 * (yIndex * nX + xIndex);
        pixels[o] = red;
        pixels[o + 1] = green;
        pixels[o + 2] = blue;
    }

    /**
     * Copies the pixels of a region (e.g. one rendered by {@link Camera#renderRegion} on another machine) into
     * this image at the region's place; regions that cover the image together build it exactly.
     *
     * @param region the rendered region to copy
     * @throws IllegalArgumentException if the region does not lie inside this image
     */
    public void writeRegion(ImageRegion region) {
        int x0 = region.getX0(), y0 = region.getY0(), w = region.getWidth(), h = region.getHeight();
        if (x0 > nX - w || y0 > nY - h) {
            throw new IllegalArgumentException("region of " + w + " x " + h + " at (" + x0 + ", " + y0
                    + ") is not inside the " + nX + " x " + nY + " image");
        }
        for (int y = y0; y < y0 + h; y++) region.copyRow(y, pixels, 3 * (y * nX + x0));
    }

    /**
     * The linear (unclamped) colour of pixel (x, y).
     *
     * @param xIndex the 0-based column
     * @param yIndex the 0-based row
     * @return a new colour of the pixel's channels
     */
    public Color getPixel(int xIndex, int yIndex) {
        checkIndex(xIndex, yIndex);
        int o = 3 * (yIndex * nX + xIndex);
        return new Color(pixels[o], pixels[o + 1], pixels[o + 2]);
    }

    private void checkIndex(int x, int y) {
        if (x < 0 || x >= nX || y < 0 || y >= nY) {
            throw new IllegalArgumentException(
                    "pixel (" + x + ", " + y + ") is outside the " + nX + " x " + nY + " image");
        }
    }

    /**
     * The image as 8-bit RGB, each channel clamped to 0..255 and rounded.
     *
     * @return a new image of the same size
     */
    public BufferedImage toBufferedImage() {
        BufferedImage image = new BufferedImage(nX, nY, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < nY; y++) {
            for (int x = 0; x < nX; x++) {
                int o = 3 * (y * nX + x);
                image.setRGB(x, y, (channel(pixels[o]) << 16) | (channel(pixels[o + 1]) << 8) | channel(pixels[o + 2]));
            }
        }
        return image;
    }

    private static int channel(double value) {
        if (!(value > 0)) return 0;
        if (value >= 255) return 255;
        return (int) Math.round(value);
    }

    /**
     * Writes {@code images/<name>.png} (folders created as needed) and returns its path.
     *
     * @return the absolute path of the written file
     */
    public Path writeToImage() {
        return writeToImage(DEFAULT_FOLDER.resolve(imageName + ".png"));
    }

    /**
     * Writes the image as PNG to {@code file}, creating missing parent folders. The bytes go to a temporary
     * file beside it first and are moved into place only when complete.
     *
     * @param file the PNG file to create or replace
     * @return the absolute path of the written file
     * @throws java.io.UncheckedIOException if the file cannot be written
     */
    public Path writeToImage(Path file) {
        return AtomicFile.write(file, "image", temp -> {
            if (!ImageIO.write(toBufferedImage(), "png", temp.toFile())) {
                throw new IOException("no PNG writer is available in this JDK");
            }
        });
    }
}
