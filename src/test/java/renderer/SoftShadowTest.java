package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static renderer.FeatureScenes.brightness;

import lighting.PointLight;
import lighting.SpotLight;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.sampling.SamplingPattern;
import scene.Scene;

/** Soft shadows from lights with a radius: penumbra width, exact visibility, transparency, hard-shadow limit. */
class SoftShadowTest {
    private static final int N = 120;
    private static final Material OPAQUE = new Material().setKd(0.5);

    private static ImageWriter render(PointLight light, Material occluder, String name) {
        Scene scene = FeatureScenes.shadowScene(light, occluder);
        Camera camera = FeatureScenes.shadowCamera(scene, N).build().renderImage();
        camera.writeToImage("tests/soft-shadow-" + name);
        return camera.getImage();
    }

    /** The floor without the occluder: the fully lit brightness of every pixel. */
    private static final ImageWriter UNOCCLUDED = render(FeatureScenes.shadowLight(), null, "unoccluded");

    /** Ambient light only: the brightness of the floor in full shadow. */
    private static final double UMBRA = 40;

    /**
     * Floor pixels of the middle row (right of the occluder itself) whose visibility, measured against the
     * unoccluded floor, is strictly between 3% and 97%.
     */
    private static int penumbraWidth(ImageWriter image) {
        int y = N / 2, count = 0;
        for (int x = N / 5; x < N; x++) {
            double visibility = (brightness(image, x, y) - UMBRA) / (brightness(UNOCCLUDED, x, y) - UMBRA);
            if (visibility > 0.03 && visibility < 0.97) count++;
        }
        return count;
    }

    @Test
    void penumbraWidensWithTheLightRadius() {
        int hard = penumbraWidth(render(FeatureScenes.shadowLight(), OPAQUE, "r0"));
        int small =
                penumbraWidth(render(FeatureScenes.shadowLight().setRadius(3).setNumSamples(64), OPAQUE, "r3"));
        int large =
                penumbraWidth(render(FeatureScenes.shadowLight().setRadius(10).setNumSamples(64), OPAQUE, "r10"));
        assertTrue(hard <= 2, "a point light has no penumbra, found " + hard + " pixels");
        assertTrue(small > hard + 4, "radius 3 penumbra " + small + " vs hard " + hard);
        assertTrue(large > small + 4, "radius 10 penumbra " + large + " vs radius 3 " + small);
    }

    @Test
    void visibilityIsExactlyOneWhenClearAndExactlyZeroDeepInTheUmbra() {
        ImageWriter hard = render(FeatureScenes.shadowLight(), OPAQUE, "hard");
        ImageWriter soft = render(FeatureScenes.shadowLight().setRadius(2).setNumSamples(81), OPAQUE, "exact");
        // Far from the shadow every shadow ray is clear: the soft image equals the hard one bit for bit.
        assertEquals(hard.getPixel(N - 2, 2), soft.getPixel(N - 2, 2));
        assertEquals(hard.getPixel(1, N - 2), soft.getPixel(1, N - 2));
        // At the centre of the shadow (x = 48, the middle of the image) every ray is blocked.
        int c = N / 2;
        assertEquals(hard.getPixel(c, c), soft.getPixel(c, c));
        assertTrue(brightness(hard, c, c) < brightness(hard, N - 2, 2) / 2, "the centre is in shadow");
    }

    @Test
    void aTransparentOccluderCastsAPartialSoftShadow() {
        ImageWriter opaque = render(FeatureScenes.shadowLight().setRadius(3).setNumSamples(64), OPAQUE, "opaque");
        ImageWriter glass = render(
                FeatureScenes.shadowLight().setRadius(3).setNumSamples(64),
                new Material().setKd(0.2).setKt(0.5),
                "transparent");
        int c = N / 2;
        double umbra = brightness(opaque, c, c), partial = brightness(glass, c, c), lit = brightness(glass, N - 2, 2);
        assertTrue(umbra < partial && partial < lit, umbra + " < " + partial + " < " + lit);
        assertTrue(penumbraWidth(glass) > 4, "the partial shadow has a soft edge");
    }

    @Test
    void behindTheSameGlassFromEveryPartOfTheDiskTheSoftLightShadesExactlyAsTheHardOne() {
        // kT 0.6: 81 rays of transmittance 0.6 summed and divided by 81 is not 0.6 in floating point; the sampler
        // must return the common value itself, fixed or adaptive, or soft shadows would change pixels (by one
        // display level, here and there) where no penumbra is.
        Material glass = new Material().setKd(0.2).setKt(0.6);
        ImageWriter hard = render(FeatureScenes.shadowLight(), glass, "glass-hard");
        ImageWriter soft = render(FeatureScenes.shadowLight().setRadius(2).setNumSamples(81), glass, "glass-soft");
        Scene scene = FeatureScenes.shadowScene(
                FeatureScenes.shadowLight().setRadius(2).setNumSamples(81), glass);
        Camera adaptive = FeatureScenes.shadowCamera(scene, N)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true))
                .build()
                .renderImage();
        int c = N / 2;
        assertEquals(hard.getPixel(c, c), soft.getPixel(c, c), "fixed count, centre of the glass's shadow");
        assertEquals(hard.getPixel(c, c), adaptive.getImage().getPixel(c, c), "adaptive");
        assertTrue(brightness(hard, c, c) < brightness(hard, N - 2, 2), "the centre is in the glass's shadow");
    }

    @Test
    void radiusZeroOrOneSampleIsExactlyTheHardShadow() {
        ImageWriter hard = render(FeatureScenes.shadowLight(), OPAQUE, "plain");
        assertNull(FeatureScenes.firstDifference(
                hard, render(FeatureScenes.shadowLight().setRadius(0).setNumSamples(81), OPAQUE, "radius0")));
        assertNull(FeatureScenes.firstDifference(
                hard, render(FeatureScenes.shadowLight().setRadius(10).setNumSamples(1), OPAQUE, "one-sample")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"GRID", "JITTERED", "RANDOM", "HALTON"})
    void everyShadowPatternGivesASoftEdge(String pattern) {
        Scene scene = FeatureScenes.shadowScene(
                FeatureScenes.shadowLight().setRadius(10).setNumSamples(49), OPAQUE);
        Camera camera = FeatureScenes.shadowCamera(scene, N)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.valueOf(pattern), false))
                .build()
                .renderImage();
        assertTrue(penumbraWidth(camera.getImage()) > 8, pattern);
    }

    @Test
    void spotLightsCastSoftShadowsToo() {
        SpotLight spot = new SpotLight(new Color(300, 300, 300), new Point(-60, 0, 50), new Vector(1, 0, -1));
        int hard = penumbraWidth(render(spot, OPAQUE, "spot-hard"));
        int soft = penumbraWidth(render(
                new SpotLight(new Color(300, 300, 300), new Point(-60, 0, 50), new Vector(1, 0, -1))
                        .setRadius(10)
                        .setNumSamples(64),
                OPAQUE,
                "spot-soft"));
        assertTrue(soft > hard + 4, "spot penumbra " + soft + " vs hard " + hard);
    }

    @Test
    void adaptiveShadowsStayCloseToTheFullBeamWithFewerRays() {
        Scene scene = FeatureScenes.shadowScene(
                FeatureScenes.shadowLight().setRadius(6).setNumSamples(81), OPAQUE);
        Camera full = FeatureScenes.shadowCamera(scene, N).build().renderImage();
        Camera adaptive = FeatureScenes.shadowCamera(scene, N)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true))
                .build()
                .renderImage();
        adaptive.writeToImage("tests/soft-shadow-adaptive");
        RayCounters f = full.getLastStatistics().rays(),
                a = adaptive.getLastStatistics().rays();
        assertTrue(a.shadow * 3 < f.shadow, a.shadow + " adaptive shadow rays vs " + f.shadow);
        assertEquals(f.shadow - a.shadow, a.samplesSaved - probesOfDisagreeingPoints(a, f), 0.0);
        // Stated tolerance: RMS difference below 1.5 and no pixel off by more than 30 (of 255).
        double rms = FeatureScenes.rmsDifference(full.getImage(), adaptive.getImage());
        double max = FeatureScenes.maxDifference(full.getImage(), adaptive.getImage());
        assertTrue(rms < 1.5 && max < 30, "rms " + rms + ", max " + max);
    }

    /**
     * Where the 9 probes disagree, they are fired on top of the full 81: the saving counter only counts points
     * where the probes sufficed, so shadow(full) - shadow(adaptive) = saved - 9 x disagreeing points.
     */
    private static long probesOfDisagreeingPoints(RayCounters adaptive, RayCounters full) {
        long points = full.shadow / 81;
        long agreeing = adaptive.samplesSaved / (81 - 9);
        return 9 * (points - agreeing);
    }

    @Test
    void badLightSettingsAreRejected() {
        PointLight light = FeatureScenes.shadowLight();
        assertTrue(assertThrows(IllegalArgumentException.class, () -> light.setRadius(-1))
                .getMessage()
                .contains("radius"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> light.setRadius(Double.NaN))
                .getMessage()
                .contains("NaN"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> light.setNumSamples(0))
                .getMessage()
                .contains("numSamples"));
    }
}
