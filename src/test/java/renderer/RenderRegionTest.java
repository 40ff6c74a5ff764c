package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/**
 * {@link Camera#renderRegion}: regions stitched with {@link ImageWriter#writeRegion} give exactly the bits of
 * {@link Camera#renderImage()}, whatever the split, order, thread count or repetition (what a distributed render
 * and its retries rely on); bad rectangles are rejected.
 */
class RenderRegionTest {
    private static final int W = 61, H = 47; // not multiples of the 16-pixel tiles nor of the splits below

    /** Every random effect: jittered anti-aliasing, soft shadows, glossy reflection (DeterminismRenderTest). */
    private static Camera jittered(int threads) {
        return base(threads)
                .setSamplingConfig(new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .build();
    }

    /** Adaptive anti-aliasing and a thin lens: the other two per-pixel random streams. */
    private static Camera adaptiveWithLens(int threads) {
        return base(threads)
                .setSamplingConfig(new SamplingConfig(9, TargetShape.RECTANGLE, SamplingPattern.RANDOM).adaptive(4))
                .setDepthOfField(12, 0.3)
                .setApertureSampling(new SamplingConfig(4, TargetShape.CIRCLE, SamplingPattern.JITTERED))
                .build();
    }

    private static Camera.Builder base(int threads) {
        return Camera.getBuilder()
                .setLocation(new Point(0, -12, 6))
                .setDirection(new Point(0, 1.5, 1), Vector.AXIS_Z)
                .setVpDistance(10)
                .setVpSize(12, 12.0 * H / W)
                .setResolution(W, H)
                .setRayTracer(DeterminismRenderTest.scene(), RayTracerType.SIMPLE)
                .setRenderSettings(RenderSettings.DEFAULT.withGlossySampling(
                        new SamplingConfig(4, TargetShape.CIRCLE, SamplingPattern.JITTERED)))
                .setThreads(threads);
    }

    /** Splits the image into cols x rows regions of uneven sizes, renders them last first, stitches them. */
    private static ImageWriter stitched(Camera camera, int cols, int rows) {
        ImageWriter image = new ImageWriter("stitched", W, H);
        for (int r = rows - 1; r >= 0; r--) {
            for (int c = cols - 1; c >= 0; c--) {
                int x0 = c * W / cols, x1 = (c + 1) * W / cols, y0 = r * H / rows, y1 = (r + 1) * H / rows;
                image.writeRegion(camera.renderRegion(x0, y0, x1 - x0, y1 - y0));
            }
        }
        return image;
    }

    private static void assertSameBits(ImageWriter expected, ImageWriter actual, String what) {
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                Color e = expected.getPixel(x, y), a = actual.getPixel(x, y);
                if (Double.doubleToRawLongBits(e.getR()) != Double.doubleToRawLongBits(a.getR())
                        || Double.doubleToRawLongBits(e.getG()) != Double.doubleToRawLongBits(a.getG())
                        || Double.doubleToRawLongBits(e.getB()) != Double.doubleToRawLongBits(a.getB())) {
                    fail(what + ": pixel " + x + "," + y + " is " + a + " instead of " + e);
                }
            }
        }
    }

    private static void assertVaried(ImageWriter image) {
        long distinct = 0;
        Color previous = null;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                Color c = image.getPixel(x, y);
                if (!c.equals(previous)) distinct++;
                previous = c;
            }
        }
        assertTrue(distinct > W * H / 2, "a varied image, so a misplaced region would show: " + distinct);
    }

    @Test
    void stitchedRegionsAreBitIdenticalToTheWholeImage() {
        ImageWriter whole = jittered(2).renderImage().getImage();
        assertVaried(whole);
        assertSameBits(whole, stitched(jittered(2), 2, 2), "2 x 2 regions");
        assertSameBits(whole, stitched(jittered(1), 4, 4), "4 x 4 regions, 1 thread");
        assertSameBits(whole, stitched(jittered(3), 3, 5), "3 x 5 regions, 3 threads");
        assertSameBits(whole, stitched(jittered(2), W, 1), "one column per region");
    }

    @Test
    void adaptiveSamplingAndDepthOfFieldStitchToTheSameBits() {
        ImageWriter whole = adaptiveWithLens(2).renderImage().getImage();
        assertVaried(whole);
        assertSameBits(whole, stitched(adaptiveWithLens(2), 3, 2), "3 x 2 regions");
    }

    @Test
    void aRegionRenderedTwiceIsIdentical() {
        Camera camera = jittered(2);
        ImageRegion first = camera.renderRegion(10, 20, 30, 17);
        ImageRegion again = jittered(1).renderRegion(10, 20, 30, 17);
        for (int y = 20; y < 37; y++) {
            for (int x = 10; x < 40; x++) assertEquals(first.getPixel(x, y), again.getPixel(x, y), x + "," + y);
        }
    }

    @Test
    void renderRegionLeavesTheImageAloneAndCountsItsPixels() {
        Camera camera = jittered(2);
        ImageRegion region = camera.renderRegion(5, 6, 7, 8);
        assertNull(camera.getImage(), "a region is not an image render");
        assertEquals(56, camera.getLastStatistics().pixels());
        assertEquals(4 * 56, camera.getLastStatistics().rays().camera);
        assertEquals(5, region.getX0());
        assertEquals(6, region.getY0());
        assertEquals(7, region.getWidth());
        assertEquals(8, region.getHeight());
    }

    @Test
    void aSerializedRegionKeepsItsBits() throws IOException, ClassNotFoundException {
        ImageRegion region = jittered(2).renderRegion(0, 0, 20, 10);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(region);
        }
        ImageRegion copy;
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            copy = (ImageRegion) in.readObject();
        }
        for (int y = 0; y < 10; y++) {
            for (int x = 0; x < 20; x++) assertEquals(region.getPixel(x, y), copy.getPixel(x, y));
        }
    }

    @Test
    void rectanglesOutsideTheImageAreRejected() {
        Camera camera = jittered(1);
        assertThrows(IllegalArgumentException.class, () -> camera.renderRegion(0, 0, 0, 5), "empty");
        assertThrows(IllegalArgumentException.class, () -> camera.renderRegion(0, 0, 5, -1), "negative height");
        assertThrows(IllegalArgumentException.class, () -> camera.renderRegion(-1, 0, 5, 5), "left of the image");
        assertThrows(IllegalArgumentException.class, () -> camera.renderRegion(0, H - 4, 5, 5), "below the image");
        IllegalArgumentException e =
                assertThrows(IllegalArgumentException.class, () -> camera.renderRegion(W - 4, 0, 5, 5));
        assertTrue(e.getMessage().contains("not inside the 61 x 47 image"), e.getMessage());
        assertThrows(
                IllegalArgumentException.class,
                () -> camera.renderRegion(Integer.MAX_VALUE, 0, 2, 2),
                "overflowing right edge");
    }

    @Test
    void aRegionMustFitTheImageItIsWrittenInto() {
        ImageRegion region = jittered(1).renderRegion(40, 30, 21, 17);
        ImageWriter small = new ImageWriter("small", 60, 47);
        assertThrows(IllegalArgumentException.class, () -> small.writeRegion(region));
        assertThrows(IllegalArgumentException.class, () -> region.getPixel(39, 30), "outside the region");
        ImageWriter fits = new ImageWriter("fits", W, H);
        fits.writeRegion(region);
        assertEquals(region.getPixel(50, 40), fits.getPixel(50, 40));
        assertNotEquals(Color.BLACK, fits.getPixel(50, 40), "a lit pixel was copied");
        assertEquals(Color.BLACK, fits.getPixel(39, 30), "pixels outside the region stay black");
    }
}
