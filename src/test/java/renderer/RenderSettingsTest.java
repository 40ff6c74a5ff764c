package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/** Unit tests for {@link RenderSettings} and {@link SamplingConfig} validation. */
class RenderSettingsTest {
    private static void assertMessage(Runnable action, String... fragments) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, action::run);
        for (String f : fragments) assertTrue(e.getMessage().contains(f), "'" + f + "' in: " + e.getMessage());
    }

    @Test
    void defaultsAndCopies() {
        RenderSettings d = RenderSettings.DEFAULT;
        assertTrue(d.useBvh());
        assertTrue(d.planEffects());
        assertEquals(10, d.maxLevel());
        RenderSettings off = d.withBvh(false);
        assertFalse(off.useBvh());
        assertTrue(d.useBvh(), "immutable");
        assertEquals(3, d.withRecursion(3, 0.01).maxLevel());
        assertEquals(0.01, d.withRecursion(3, 0.01).minAttenuation());
        assertFalse(d.withPlanEffects(false).planEffects());
        assertEquals(8, d.withBvhBuild(8, 2).bvhBins());
    }

    @Test
    void badValuesAreRejected() {
        RenderSettings d = RenderSettings.DEFAULT;
        assertMessage(() -> d.withBvhBuild(1, 4), "bvhBins", "1");
        assertMessage(() -> d.withBvhBuild(16, 0), "bvhMaxLeafSize", "0");
        assertMessage(() -> d.withRecursion(0, 0.001), "maxLevel", "0");
        assertMessage(() -> d.withRecursion(5, 1), "minAttenuation", "1.0");
        assertMessage(() -> d.withRecursion(5, -0.1), "minAttenuation", "-0.1");
        assertMessage(() -> d.withShadowSampling(null, false), "shadowPattern");
        assertMessage(() -> d.withGlossySampling(null), "glossySampling");
        assertMessage(() -> new SamplingConfig(0, TargetShape.RECTANGLE, SamplingPattern.GRID), "sampleCount", "0");
        assertMessage(
                () -> new SamplingConfig(4, TargetShape.RECTANGLE, SamplingPattern.GRID).adaptive(0), "threshold", "0");
        assertFalse(SamplingConfig.NONE.isEnabled());
    }
}
