package sceneio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Texture;

/** Decoding of PNG and JPEG textures: values as stored (no gamma change), grey, palette, 16-bit, caching. */
class TextureLoaderTest {
    @TempDir
    Path dir;

    private final List<String> files = new ArrayList<>();

    private TextureLoader loader() {
        return new TextureLoader(new FileConfinement(dir, List.of()), files);
    }

    private static double[] centre(Texture t) {
        double[] out = new double[3];
        t.lookup(0.5 / t.getWidth(), 1 - 0.5 / t.getHeight(), out); // the top-left texel's centre
        return out;
    }

    @Test
    void rgbValuesAreDividedBy255WithoutAnSrgbDecode() throws Exception {
        BufferedImage image = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, (51 << 16) | (128 << 8) | 255);
        ImageIO.write(image, "png", dir.resolve("rgb.png").toFile());
        Texture t = loader().load("rgb.png", "rgb.png", Texture.Wrap.REPEAT);
        assertArrayEquals(new double[] {51 / 255f, 128 / 255f, 1}, centre(t), 1e-7);
    }

    @Test
    void greyImagesKeepTheirValues() throws Exception {
        BufferedImage grey = new BufferedImage(1, 1, BufferedImage.TYPE_BYTE_GRAY);
        grey.getRaster().setSample(0, 0, 0, 64);
        ImageIO.write(grey, "png", dir.resolve("grey.png").toFile());
        // getRGB would brighten 64 to about 136 (it takes grey as linear); the texture keeps 64.
        assertArrayEquals(
                new double[] {64 / 255f, 64 / 255f, 64 / 255f},
                centre(loader().load("grey.png", "g", Texture.Wrap.CLAMP)),
                1e-7);
        BufferedImage deep = new BufferedImage(1, 1, BufferedImage.TYPE_USHORT_GRAY);
        deep.getRaster().setSample(0, 0, 0, 65535);
        ImageIO.write(deep, "png", dir.resolve("deep.png").toFile());
        assertArrayEquals(new double[] {1, 1, 1}, centre(loader().load("deep.png", "d", Texture.Wrap.CLAMP)), 1e-7);
    }

    @Test
    void paletteImagesAndJpegsAreRead() throws Exception {
        IndexColorModel palette =
                new IndexColorModel(8, 2, new byte[] {0, (byte) 200}, new byte[] {0, 100}, new byte[] {0, 50});
        BufferedImage indexed = new BufferedImage(2, 1, BufferedImage.TYPE_BYTE_INDEXED, palette);
        indexed.getRaster().setSample(0, 0, 0, 1);
        ImageIO.write(indexed, "png", dir.resolve("indexed.png").toFile());
        assertArrayEquals(
                new double[] {200 / 255f, 100 / 255f, 50 / 255f},
                centre(loader().load("indexed.png", "i", Texture.Wrap.CLAMP)),
                1e-7);
        BufferedImage flat = new BufferedImage(16, 16, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 16; y++) for (int x = 0; x < 16; x++) flat.setRGB(x, y, 0x80C040);
        ImageIO.write(flat, "jpeg", dir.resolve("flat.jpg").toFile());
        double[] jpeg = centre(loader().load("flat.jpg", "j", Texture.Wrap.REPEAT));
        // Lossy, but a flat colour survives within a few steps.
        assertArrayEquals(new double[] {128 / 255.0, 192 / 255.0, 64 / 255.0}, jpeg, 4 / 255.0);
    }

    @Test
    void eachFileIsDecodedOncePerWrapAndListedOnce() throws Exception {
        ImageIO.write(
                new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB),
                "png",
                dir.resolve("a.png").toFile());
        TextureLoader loader = loader();
        Texture repeat = loader.load("a.png", "a.png", Texture.Wrap.REPEAT);
        Texture clamp = loader.load("./a.png", "a.png", Texture.Wrap.CLAMP);
        assertSame(repeat, loader.load("a.png", "a.png", Texture.Wrap.REPEAT));
        assertSame(clamp, loader.load("a.png", "a.png", Texture.Wrap.CLAMP));
        assertNotSame(repeat, clamp);
        assertEquals(Texture.Wrap.CLAMP, clamp.getWrap());
        assertEquals(List.of("a.png"), files, "the same file by another name is the same file");
    }
}
