package primitives;

/**
 * An image texture held as a plain array of linear factors (0 to 1 per channel) and looked up with bilinear
 * filtering, allocation-free. Texture coordinates follow OBJ: (0, 0) is the image's lower-left corner, (1, 1) its
 * upper-right; the centre of texel (column i, row j counted from the top) is at u = (i + 0.5) / width,
 * v = 1 - (j + 0.5) / height, where a lookup returns that texel exactly. Outside [0, 1] the {@link Wrap} mode
 * decides which texel a coordinate means.
 *
 * <p>The factors are the image's 8-bit values divided by 255, without an sRGB decode: the library's colours are
 * display values (0..255 written to the image unchanged), so a white light on a kD 1 surface reproduces the image.
 * Decoding is the tool layer's business ({@code sceneio}); the core only filters the numbers it is given.
 */
public final class Texture {
    /** What a texture coordinate outside [0, 1] means. */
    public enum Wrap {
        /** The image tiles the plane: u and u + 1 are the same point (the OBJ/MTL default). */
        REPEAT,
        /** The edge texels extend outward: u below 0 is 0, above 1 is 1. */
        CLAMP,
        /** The image tiles the plane mirrored every other tile, so tiles meet without seams. */
        MIRROR
    }

    /** Largest texture side (texels): 2^14. */
    public static final int MAX_SIDE = 1 << 14;
    /** Most texels in one texture: 2^24 (4096 x 4096), 192 MiB as floats, so 3 values per texel index an array. */
    public static final int MAX_TEXELS = 1 << 24;

    private final int width, height;
    /** Red, green, blue per texel, rows from the top of the image. */
    private final float[] rgb;

    private final Wrap wrap;

    /**
     * A texture of {@code width x height} texels.
     *
     * @param width texels per row, 1 to {@link #MAX_SIDE}
     * @param height rows, 1 to {@link #MAX_SIDE}, at most {@link #MAX_TEXELS} texels in all
     * @param rgb red, green, blue per texel, row by row from the top; finite and at least 0 (copied)
     * @param wrap what coordinates outside [0, 1] mean; not null
     * @throws IllegalArgumentException if a size is out of range, the array's length is not 3 per texel or a value
     *     is negative or not finite
     */
    public Texture(int width, int height, float[] rgb, Wrap wrap) {
        Util.requireNonNull(rgb, "texture texels");
        Util.requireNonNull(wrap, "texture wrap mode");
        if (width < 1 || height < 1 || width > MAX_SIDE || height > MAX_SIDE || (long) width * height > MAX_TEXELS) {
            throw new IllegalArgumentException("a texture must be 1 to " + MAX_SIDE + " texels on each side and have at"
                    + " most " + MAX_TEXELS + " texels, but was " + width + " x " + height);
        }
        if (rgb.length != 3 * width * height) {
            throw new IllegalArgumentException("a " + width + " x " + height + " texture needs " + 3 * width * height
                    + " values (red, green, blue per texel), but had " + rgb.length);
        }
        for (int i = 0; i < rgb.length; i++) {
            if (!(rgb[i] >= 0 && rgb[i] <= Float.MAX_VALUE)) {
                throw new IllegalArgumentException(
                        "texture value " + i + " must be finite and at least 0, but was " + rgb[i]);
            }
        }
        this.width = width;
        this.height = height;
        this.rgb = rgb.clone();
        this.wrap = wrap;
    }

    /**
     * The same texels with another wrap mode (the array is shared, not copied).
     *
     * @param mode the new wrap mode; not null
     * @return a texture of the same texels
     */
    public Texture withWrap(Wrap mode) {
        Util.requireNonNull(mode, "texture wrap mode");
        return mode == wrap ? this : new Texture(this, mode);
    }

    private Texture(Texture texels, Wrap wrap) {
        this.width = texels.width;
        this.height = texels.height;
        this.rgb = texels.rgb;
        this.wrap = wrap;
    }

    /**
     * Texels per row.
     *
     * @return the width, at least 1
     */
    public int getWidth() {
        return width;
    }

    /**
     * Number of rows.
     *
     * @return the height, at least 1
     */
    public int getHeight() {
        return height;
    }

    /**
     * The wrap mode.
     *
     * @return what coordinates outside [0, 1] mean
     */
    public Wrap getWrap() {
        return wrap;
    }

    /**
     * The bilinearly filtered value at texture coordinates (u, v) into {@code out[0..2]} (red, green, blue).
     * Allocates nothing; a non-finite coordinate counts as 0.
     *
     * @param u the horizontal coordinate, 0 at the image's left edge, 1 at its right
     * @param v the vertical coordinate, 0 at the image's bottom edge, 1 at its top
     * @param out receives red, green, blue; length at least 3
     */
    public void lookup(double u, double v, double[] out) {
        // Texel space with texel centres on integers; the wrap reduces the coordinate first, so any finite value
        // gives indices near the image and the products below cannot overflow an int.
        double x = reduce(u) * width - 0.5;
        double y = (1 - reduce(v)) * height - 0.5;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = (int) fx, y0 = (int) fy;
        int c0 = column(x0), c1 = column(x0 + 1), r0 = row(y0), r1 = row(y0 + 1);
        int i00 = 3 * (r0 * width + c0), i01 = 3 * (r0 * width + c1);
        int i10 = 3 * (r1 * width + c0), i11 = 3 * (r1 * width + c1);
        double w00 = (1 - ax) * (1 - ay), w01 = ax * (1 - ay), w10 = (1 - ax) * ay, w11 = ax * ay;
        for (int k = 0; k < 3; k++) {
            out[k] = w00 * rgb[i00 + k] + w01 * rgb[i01 + k] + w10 * rgb[i10 + k] + w11 * rgb[i11 + k];
        }
    }

    /** The coordinate brought into one period of the wrap mode: [0, 1] for clamp and repeat, [0, 2) for mirror. */
    private double reduce(double t) {
        if (!Double.isFinite(t)) return 0;
        return switch (wrap) {
            case CLAMP -> Math.min(1, Math.max(0, t));
            case REPEAT -> t - Math.floor(t);
            case MIRROR -> t - 2 * Math.floor(t / 2);
        };
    }

    private int column(int i) {
        return wrapIndex(i, width);
    }

    private int row(int j) {
        return wrapIndex(j, height);
    }

    /** Texel index {@code i} (at most one period plus one outside the image) inside [0, n). */
    private int wrapIndex(int i, int n) {
        return switch (wrap) {
            case CLAMP -> Math.min(n - 1, Math.max(0, i));
            case REPEAT -> Math.floorMod(i, n);
            case MIRROR -> {
                int m = Math.floorMod(i, 2 * n);
                yield m < n ? m : 2 * n - 1 - m;
            }
        };
    }

    @Override
    public String toString() {
        return "Texture{" + width + " x " + height + ", " + wrap + "}";
    }
}
