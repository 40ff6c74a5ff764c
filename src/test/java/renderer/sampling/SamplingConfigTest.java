package renderer.sampling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SamplingConfigTest {
    @ParameterizedTest
    @ValueSource(ints = {0, -1, Integer.MIN_VALUE})
    void countBelowOneIsRejectedNamingTheParameter(int count) {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class,
                () -> new SamplingConfig(count, TargetShape.CIRCLE, SamplingPattern.JITTERED));
        assertTrue(e.getMessage().contains("sampleCount") && e.getMessage().contains(String.valueOf(count)));
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, -1, Double.NaN, Double.POSITIVE_INFINITY})
    void adaptiveThresholdMustBePositive(double threshold) {
        SamplingConfig c = new SamplingConfig(81, TargetShape.RECTANGLE, SamplingPattern.GRID);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.adaptive(threshold));
        assertTrue(e.getMessage().contains("threshold"), e.getMessage());
    }

    @Test
    void nullShapeOrPatternIsRejected() {
        assertThrows(NullPointerException.class, () -> new SamplingConfig(4, null, SamplingPattern.GRID));
        assertThrows(NullPointerException.class, () -> new SamplingConfig(4, TargetShape.CIRCLE, null));
    }

    @Test
    void adaptiveKeepsTheCountAsMaximum() {
        SamplingConfig c = new SamplingConfig(81, TargetShape.RECTANGLE, SamplingPattern.GRID).adaptive(10);
        assertTrue(c.isAdaptive());
        assertEquals(81, c.getSampleCount());
        assertEquals(10, c.getAdaptiveThreshold());
        assertFalse(SamplingConfig.NONE.isEnabled());
        assertFalse(SamplingConfig.NONE.isAdaptive());
    }
}
