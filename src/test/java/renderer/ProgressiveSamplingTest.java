package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import sceneio.LoadedScene;
import sceneio.SceneLoader;

/**
 * Progressive sampling is honest: on the soft-shadow scene (geometry edges and penumbrae; 4 jittered shadow rays per
 * camera sample), a render asked for a target RMSE lands at most 25% above it, measured against a converged
 * reference, and the error it predicts lies within 25% of the error measured. Its samples are the same for any
 * number of threads and with the BVH off.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ProgressiveSamplingTest {
    private static final int WIDTH = 96, HEIGHT = 64;
    private ImageWriter reference;

    private static Camera camera() throws Exception {
        String json = Files.readString(Path.of("scenes/soft-shadows.json"))
                .replace("\"width\": 480", "\"width\": " + WIDTH)
                .replace("\"height\": 320", "\"height\": " + HEIGHT)
                .replace("\"samples\": 36 }", "\"samples\": 4 }")
                .replace("\"adaptiveShadows\": true", "\"adaptiveShadows\": false");
        LoadedScene loaded = SceneLoader.load(json, "soft-shadows.json", Path.of("scenes"));
        return loaded.camera();
    }

    @BeforeAll
    void renderReference() throws Exception {
        Camera c = camera();
        c.setSamplingConfig(new SamplingConfig(1024, TargetShape.RECTANGLE, SamplingPattern.HALTON));
        reference = c.renderImage().getImage();
    }

    static Stream<Double> targets() {
        return Stream.of(4.0, 2.0, 1.0);
    }

    @ParameterizedTest(name = "target RMSE {0}")
    @MethodSource("targets")
    void aTargetErrorRenderLandsNearItsTargetAndPredictsItsError(double target) throws Exception {
        Camera c = camera().setProgressive(ProgressiveSettings.targetError(target));
        ImageWriter image = c.renderImage().getImage();
        ProgressiveReport report = c.getLastProgressiveReport();
        double measured = rmse(image, reference);
        System.out.printf("target %.2f: measured %.3f, %s%n", target, measured, report.describe());
        assertTrue(measured <= 1.25 * target, "measured RMSE " + measured + " for target " + target);
        assertTrue(
                Math.abs(report.predictedError() - measured) <= 0.25 * measured,
                "predicted " + report.predictedError() + ", measured " + measured);
        assertTrue(
                report.predictedError() <= target || report.maxSamples() == report.minSamples(),
                "the render stopped at its target: " + report.describe());
        assertEquals(report.samples(), c.getLastStatistics().rays().camera, "every sample is one camera ray");
    }

    /**
     * The same honesty where every sample goes through the pixel's centre (one camera ray per pixel: only the soft
     * shadows are refined) and a pixel starts from one sample per half: the POV-Ray comparison's scene, measured
     * against its own render with 2,048 stratified shadow rays per pixel.
     */
    @ParameterizedTest(name = "target RMSE {0}")
    @MethodSource("targets")
    void aCentreSampledRenderFromOneSamplePerHalfLandsNearItsTarget(double target) throws Exception {
        Camera c = centreSampled().camera().setProgressive(ProgressiveSettings.targetError(target));
        ImageWriter image = c.renderImage().getImage();
        ProgressiveReport report = c.getLastProgressiveReport();
        double measured = rmse(image, centreReference());
        System.out.printf("centre, target %.2f: measured %.3f, %s%n", target, measured, report.describe());
        assertEquals(2, report.minSamples(), "one sample per half to start with");
        assertTrue(measured <= 1.25 * target, "measured RMSE " + measured + " for target " + target);
        assertTrue(
                Math.abs(report.predictedError() - measured) <= 0.25 * measured,
                "predicted " + report.predictedError() + ", measured " + measured);
    }

    private ImageWriter centreReference;

    private ImageWriter centreReference() throws Exception {
        if (centreReference == null) {
            LoadedScene loaded = centreSampled();
            for (lighting.LightSource light : loaded.scene().lights) {
                if (light instanceof lighting.PointLight point && point.isSoft()) point.setNumSamples(2048);
            }
            Camera c = loaded.camera();
            c.setRenderSettings(c.getRenderSettings().withShadowSampling(SamplingPattern.JITTERED, false));
            centreReference = c.renderImage().getImage();
        }
        return centreReference;
    }

    private static LoadedScene centreSampled() throws Exception {
        String json = Files.readString(Path.of("scenes/povray/soft-shadow.json"))
                .replace("\"width\": 256", "\"width\": 96")
                .replace("\"height\": 256", "\"height\": 96");
        return SceneLoader.load(json, "soft-shadow.json", Path.of("scenes/povray"));
    }

    @Test
    void theSamplesAreTheSameForAnyThreadsAndWithoutTheBvh() throws Exception {
        Camera two = camera().setProgressive(ProgressiveSettings.targetError(1)).setThreads(2);
        Camera one = camera().setProgressive(ProgressiveSettings.targetError(1)).setThreads(1);
        Camera flat =
                camera().setProgressive(ProgressiveSettings.targetError(1)).setBvh(false);
        ImageWriter a = two.renderImage().getImage();
        assertNull(FeatureScenes.firstDifference(a, one.renderImage().getImage()));
        assertNull(FeatureScenes.firstDifference(a, flat.renderImage().getImage()));
        assertEquals(two.getLastProgressiveReport(), one.getLastProgressiveReport());
    }

    @Test
    void aTimeBudgetRenderGivesACompleteImageWithItsPrediction() throws Exception {
        Camera c = camera().setProgressive(ProgressiveSettings.timeBudget(0.5));
        ImageWriter image = c.renderImage().getImage();
        ProgressiveReport report = c.getLastProgressiveReport();
        assertTrue(report.samples() >= 16L * WIDTH * HEIGHT, report.describe());
        assertTrue(report.passes() >= 1 && report.predictedError() > 0, report.describe());
        // Whatever the time allowed, the image is the mean of every pixel's samples: never worse than the first pass.
        assertTrue(rmse(image, reference) < 6, "RMSE " + rmse(image, reference));
    }

    @Test
    void regionsAndBadSettingsAreRefusedWithTheReason() throws Exception {
        Camera c = camera().setProgressive(ProgressiveSettings.targetError(2));
        assertTrue(assertThrows(IllegalStateException.class, () -> c.renderRegion(0, 0, 8, 8))
                .getMessage()
                .contains("whole image"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new ProgressiveSettings(1, 1, 16, 64))
                .getMessage()
                .contains("exactly one"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new ProgressiveSettings(0, 0, 16, 64))
                .getMessage()
                .contains("exactly one"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ProgressiveSettings.targetError(-1))
                .getMessage()
                .contains("(0, 255]"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ProgressiveSettings.timeBudget(0))
                .getMessage()
                .contains("(0, 1e7]"));
        assertTrue(assertThrows(
                        IllegalArgumentException.class,
                        () -> ProgressiveSettings.targetError(1).withSamples(5, 64))
                .getMessage()
                .contains("even"));
        assertTrue(assertThrows(
                        IllegalArgumentException.class,
                        () -> ProgressiveSettings.targetError(1).withSamples(16, 8))
                .getMessage()
                .contains("maximum samples"));
    }

    /** RMSE of the 0..255-clamped channels. */
    static double rmse(ImageWriter a, ImageWriter b) {
        double sum = 0;
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                var p = ImageMaps.clamp(a.getPixel(x, y));
                var q = ImageMaps.clamp(b.getPixel(x, y));
                sum += sq(p.getR() - q.getR()) + sq(p.getG() - q.getG()) + sq(p.getB() - q.getB());
            }
        }
        return Math.sqrt(sum / (3.0 * a.getNx() * a.getNy()));
    }

    private static double sq(double v) {
        return v * v;
    }
}
