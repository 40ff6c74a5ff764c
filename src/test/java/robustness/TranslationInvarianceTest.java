package robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import renderer.ImageWriter;

/**
 * A scene moved 1e6 or 1e9 away from the origin (camera and light with it) renders the same image. Stated
 * tolerance: fewer than 0.5% of the pixels differ by more than 1 of 255, and no pixel is NaN or infinite.
 */
class TranslationInvarianceTest {
    private static final int SIZE = 90;
    private static final ImageWriter REFERENCE = TranslationProbe.render(0, SIZE, true);

    @ParameterizedTest
    @ValueSource(doubles = {1e6, 1e9})
    void farAwayTheImageIsTheSame(double offset) {
        TranslationProbe.Result r =
                TranslationProbe.compare(REFERENCE, offset, TranslationProbe.render(offset, SIZE, true));
        assertEquals(0, r.nonFinitePixels());
        assertTrue(r.differingFraction() < 0.005, "differing pixels: " + r);
    }

    @Test
    void theReferenceItselfHasNoNonFinitePixel() {
        assertEquals(0, TranslationProbe.compare(REFERENCE, 0, REFERENCE).nonFinitePixels());
    }

    @Test
    void bvhEqualsBruteForceFarAway() {
        assertNull(firstDifference(TranslationProbe.render(1e9, 48, true), TranslationProbe.render(1e9, 48, false)));
    }

    private static String firstDifference(ImageWriter a, ImageWriter b) {
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                if (!a.getPixel(x, y).equals(b.getPixel(x, y))) return x + "," + y;
            }
        }
        return null;
    }
}
