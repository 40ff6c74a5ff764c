package sceneio;

import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;
import primitives.Printable;
import primitives.Texture;
import renderer.RenderMemory;

/**
 * Loads the image textures of one scene (PNG or JPEG, through {@code javax.imageio}), each file once however many
 * materials use it. Every file goes through the scene's {@link FileConfinement} first; then the size of the file,
 * the image's dimensions (read from its header, before anything is decoded) and the heap are checked, so a huge or
 * hostile image is refused with the figures rather than exhausting memory.
 *
 * <p>Texels become factors 0..1 (8-bit value / 255, 16-bit / 65535) with no sRGB decode: the library's colours are
 * display values, written to images unchanged, so a texture under white light on a kD 1 surface shows as it is
 * (see {@link Texture}). Alpha is ignored; greyscale images give grey texels.
 */
final class TextureLoader {
    /** Largest image file read: 64 MiB. */
    static final long MAX_BYTES = 64L << 20;
    /** Heap per texel while loading: the decoded image (up to 8 bytes) and the texture's floats (12). */
    static final int BYTES_PER_TEXEL = 20;

    private final FileConfinement confinement;
    /** Receives the reference of each image file read. */
    private final List<String> files;
    /** Decoded textures by real path, one per wrap mode used (sharing the texels). */
    private final Map<Path, Texture[]> loaded = new HashMap<>();

    TextureLoader(FileConfinement confinement, List<String> files) {
        this.confinement = confinement;
        this.files = files;
    }

    /** A texture that cannot be loaded: the message says which file and why. */
    static final class TextureException extends Exception {
        TextureException(String message, Throwable cause) {
            super(Printable.message(message), cause);
        }
    }

    /**
     * The texture in the file {@code reference} (relative to the scene file's folder), shown as {@code name} in
     * messages, with wrap mode {@code wrap}.
     */
    Texture load(String reference, String name, Texture.Wrap wrap) throws TextureException {
        String quoted = "texture \"" + Printable.of(name) + "\"";
        Path path;
        try {
            path = confinement.resolve("texture file", reference);
        } catch (IllegalArgumentException e) {
            throw new TextureException(e.getMessage(), e);
        }
        Texture[] wraps = loaded.get(path);
        if (wraps == null) {
            Texture decoded = decode(path, quoted);
            wraps = new Texture[Texture.Wrap.values().length];
            wraps[decoded.getWrap().ordinal()] = decoded;
            loaded.put(path, wraps);
            files.add(reference);
        }
        Texture texture = wraps[wrap.ordinal()];
        if (texture == null) {
            texture = wraps[Texture.Wrap.REPEAT.ordinal()];
            for (Texture t : wraps) texture = t != null ? t : texture;
            texture = texture.withWrap(wrap);
            wraps[wrap.ordinal()] = texture;
        }
        return texture;
    }

    private static Texture decode(Path path, String quoted) throws TextureException {
        if (!Files.exists(path, LinkOption.NOFOLLOW_LINKS)) {
            throw new TextureException(quoted + " not found (looked for " + Printable.of(path.toString()) + ")", null);
        }
        if (!Files.isRegularFile(path)) throw new TextureException(quoted + " is not a regular file", null);
        try {
            long bytes = Files.size(path);
            if (bytes > MAX_BYTES) {
                throw new TextureException(
                        String.format(
                                Locale.ROOT,
                                "%s has %,d bytes; an image file may have at most %,d (64 MiB)",
                                quoted,
                                bytes,
                                MAX_BYTES),
                        null);
            }
            try (ImageInputStream in = new FileImageInputStream(path.toFile())) {
                Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
                ImageReader reader = null;
                while (readers.hasNext() && reader == null) {
                    ImageReader r = readers.next();
                    String format = r.getFormatName().toLowerCase(Locale.ROOT);
                    if (format.equals("png") || format.equals("jpeg") || format.equals("jpg")) reader = r;
                }
                if (reader == null) throw new TextureException(quoted + " is not a PNG or JPEG image", null);
                try {
                    reader.setInput(in, true, true);
                    int width = reader.getWidth(0), height = reader.getHeight(0);
                    checkSize(quoted, width, height);
                    BufferedImage image = reader.read(0);
                    return texture(image);
                } finally {
                    reader.dispose();
                }
            }
        } catch (IOException | RuntimeException e) {
            // A damaged file: ImageIO's decoders report it as IOException or, for some damage, a runtime exception.
            throw new TextureException(quoted + " cannot be read as a PNG or JPEG image: " + e.getMessage(), e);
        }
    }

    private static void checkSize(String quoted, int width, int height) throws TextureException {
        if (width < 1
                || height < 1
                || width > Texture.MAX_SIDE
                || height > Texture.MAX_SIDE
                || (long) width * height > Texture.MAX_TEXELS) {
            throw new TextureException(
                    String.format(
                            Locale.ROOT,
                            "%s is %d x %d pixels; a texture may have at most %,d on a side and %,d in all",
                            quoted,
                            width,
                            height,
                            Texture.MAX_SIDE,
                            Texture.MAX_TEXELS),
                    null);
        }
        long need = (long) width * height * BYTES_PER_TEXEL, heap = RenderMemory.available();
        if (need > heap) {
            throw new TextureException(
                    quoted + " (" + width + " x " + height + ") needs about " + RenderMemory.bytes(need)
                            + " of memory to load, but this JVM could give " + RenderMemory.bytes(heap)
                            + "; use a smaller image or give Java more memory (-Xmx)",
                    null);
        }
    }

    /** The image's colours as factors 0..1, rows from the top. */
    private static Texture texture(BufferedImage image) {
        int width = image.getWidth(), height = image.getHeight();
        float[] rgb = new float[3 * width * height];
        Raster raster = image.getRaster();
        boolean grey = image.getColorModel().getColorSpace().getType() == ColorSpace.TYPE_GRAY;
        if (grey) {
            // getRGB would treat the grey values as linear and brighten them; the values are taken as they are.
            int bits = image.getColorModel().getComponentSize(0);
            float max = (1 << bits) - 1;
            for (int y = 0, i = 0; y < height; y++) {
                for (int x = 0; x < width; x++, i += 3) {
                    float value = raster.getSample(x, y, 0) / max;
                    rgb[i] = rgb[i + 1] = rgb[i + 2] = value;
                }
            }
        } else {
            for (int y = 0, i = 0; y < height; y++) {
                for (int x = 0; x < width; x++, i += 3) {
                    int argb = image.getRGB(x, y);
                    rgb[i] = ((argb >> 16) & 0xff) / 255f;
                    rgb[i + 1] = ((argb >> 8) & 0xff) / 255f;
                    rgb[i + 2] = (argb & 0xff) / 255f;
                }
            }
        }
        return new Texture(width, height, rgb, Texture.Wrap.REPEAT);
    }
}
