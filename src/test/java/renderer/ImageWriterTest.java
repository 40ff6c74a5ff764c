package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Color;

/** Unit tests for {@link ImageWriter}: PNG round trip, clamping at write time, bad names, no partial files. */
class ImageWriterTest {
    @TempDir
    Path temp;

    /** A 16 x 8 test pattern: red grows to the right, green downward, blue is a checker. */
    private static ImageWriter pattern(String name) {
        ImageWriter w = new ImageWriter(name, 16, 8);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 16; x++) w.writePixel(x, y, new Color(x * 17, y * 36, (x + y) % 2 == 0 ? 200 : 3));
        }
        return w;
    }

    private static int[] rgb(BufferedImage image, int x, int y) {
        int p = image.getRGB(x, y);
        return new int[] {(p >> 16) & 255, (p >> 8) & 255, p & 255};
    }

    private static List<Path> listFiles(Path folder) throws IOException {
        try (Stream<Path> s = Files.list(folder)) {
            return s.toList();
        }
    }

    @Test
    void writesAPngThatReadsBackWithTheSamePixels() throws IOException {
        Path file = pattern("ignored").writeToImage(temp.resolve("pattern.png"));
        assertEquals(temp.resolve("pattern.png").toAbsolutePath(), file);
        BufferedImage read = ImageIO.read(file.toFile());
        assertEquals(16, read.getWidth());
        assertEquals(8, read.getHeight());
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 16; x++) {
                int[] expected = {x * 17, y * 36, (x + y) % 2 == 0 ? 200 : 3};
                int[] actual = rgb(read, x, y);
                for (int c = 0; c < 3; c++) assertEquals(expected[c], actual[c], "pixel " + x + "," + y);
            }
        }
        // only the image is left in the folder: no temporary file
        assertEquals(List.of(file), listFiles(temp));
    }

    @Test
    void writesToImagesFolderByDefaultCreatingSubfolders() throws IOException {
        Path file = pattern("test-imagewriter/sub/pattern").writeToImage();
        assertEquals(
                ImageWriter.DEFAULT_FOLDER
                        .resolve("test-imagewriter/sub/pattern.png")
                        .toAbsolutePath(),
                file);
        assertTrue(Files.isRegularFile(file));
        assertEquals(16, ImageIO.read(file.toFile()).getWidth());
    }

    @Test
    void clampsOnlyWhenWriting() {
        ImageWriter w = new ImageWriter("clamp", 5, 1);
        w.writePixel(0, 0, new Color(300, -20, 255));
        w.writePixel(1, 0, new Color(254.4, 254.6, 0.49));
        w.writePixel(2, 0, new Color(1e300, -1e300, 127.5));
        w.writePixel(3, 0, new Color(Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0.5));
        // the linear values are kept as they are
        assertEquals(new Color(300, -20, 255), w.getPixel(0, 0));
        BufferedImage image = w.toBufferedImage();
        assertArrayEquals(new int[] {255, 0, 255}, rgb(image, 0, 0));
        assertArrayEquals(new int[] {254, 255, 0}, rgb(image, 1, 0));
        assertArrayEquals(new int[] {255, 0, 128}, rgb(image, 2, 0));
        assertArrayEquals(new int[] {255, 0, 1}, rgb(image, 3, 0));
        // never written: black
        assertArrayEquals(new int[] {0, 0, 0}, rgb(image, 4, 0));
    }

    private static void assertArrayEquals(int[] expected, int[] actual) {
        org.junit.jupiter.api.Assertions.assertArrayEquals(
                expected, actual, java.util.Arrays.toString(expected) + " vs " + java.util.Arrays.toString(actual));
    }

    @Test
    void pixelIndicesAndNaNAreValidated() {
        ImageWriter w = new ImageWriter("bounds", 4, 3);
        IllegalArgumentException e =
                assertThrows(IllegalArgumentException.class, () -> w.writePixel(4, 0, Color.BLACK));
        assertTrue(e.getMessage().contains("(4, 0)") && e.getMessage().contains("4 x 3"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> w.writePixel(0, 3, Color.BLACK));
        assertThrows(IllegalArgumentException.class, () -> w.writePixel(-1, 0, Color.BLACK));
        assertThrows(IllegalArgumentException.class, () -> w.getPixel(0, -1));
        e = assertThrows(IllegalArgumentException.class, () -> w.writePixel(1, 1, new Color(0, Double.NaN, 0)));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
    }

    @Test
    void resolutionIsValidated() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("x", 0, 10));
        assertTrue(e.getMessage().contains("0 x 10"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new ImageWriter("x", 10, -1));
        assertThrows(IllegalArgumentException.class, () -> new ImageWriter("x", 1 << 15, 1 << 15));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "   ", "/tmp/absolute", "../escape", "a/../../b", ".."})
    void badNamesAreRejected(String name) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter(name, 2, 2));
        assertTrue(e.getMessage().contains("image name"), e.getMessage());
    }

    @Test
    void nullNameIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> new ImageWriter(null, 2, 2));
    }

    @Test
    void failedWriteLeavesNoPartialFile() throws IOException {
        // the target is an existing, non-empty directory: the move cannot replace it
        Path target = temp.resolve("taken.png");
        Files.createDirectories(target);
        Files.writeString(target.resolve("keep.txt"), "keep");
        UncheckedIOException e =
                assertThrows(UncheckedIOException.class, () -> pattern("x").writeToImage(target));
        assertTrue(e.getMessage().contains("taken.png"), e.getMessage());
        // nothing but the directory remains: the temporary file was removed
        assertEquals(List.of(target), listFiles(temp));
        assertEquals(List.of(target.resolve("keep.txt")), listFiles(target));

        // the parent "folder" is a regular file: nothing can be created
        Path file = temp.resolve("plain-file");
        Files.writeString(file, "not a folder");
        assertThrows(UncheckedIOException.class, () -> pattern("x").writeToImage(file.resolve("image.png")));
        assertEquals("not a folder", Files.readString(file));
        assertEquals(2, listFiles(temp).size());
    }

    @Test
    void anExistingImageIsReplacedWhole() throws IOException {
        Path target = temp.resolve("replace.png");
        ImageWriter first = new ImageWriter("a", 3, 3);
        first.writePixel(1, 1, new Color(255, 0, 0));
        first.writeToImage(target);
        ImageWriter second = new ImageWriter("b", 5, 2);
        second.writePixel(4, 1, new Color(0, 0, 255));
        second.writeToImage(target);
        BufferedImage read = ImageIO.read(target.toFile());
        assertEquals(5, read.getWidth());
        assertArrayEquals(new int[] {0, 0, 255}, rgb(read, 4, 1));
        assertEquals(List.of(target), listFiles(temp));
        assertFalse(Files.exists(temp.resolve("replace.png.tmp")));
    }
}
