package report;

import app.StreetOptions;
import app.StreetScene;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import renderer.Camera;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/**
 * Anti-aliasing and soft shadows together on the street scene. The fixed variants are set the way StreetSceneTest
 * sets them: {@code n} camera rays per pixel and {@code n} shadow rays per lamp at every hit, so they cost about
 * {@code n * n} shadow rays per pixel and lamp. The adaptive variants spend {@code n} camera rays per pixel (GRID:
 * adaptive subdivision, at most {@code n}; HALTON: exactly {@code n}) and adaptive shadows of at most
 * {@link #ADAPTIVE_SHADOW_RAYS} rays per lamp at every hit: each camera ray draws its own shadow rays, so a pixel's
 * camera rays together sample the lamp's disk up to {@code n * 9} times. The verdict states how long the best adaptive
 * variant takes to reach the error of fixed 81-sample GRID anti-aliasing plus 81-sample soft shadows.
 */
public final class StreetExperiment implements Experiment {
    /** The configuration the adaptive one is measured against (the one users write in StreetSceneTest). */
    static final int BASELINE_SAMPLES = 81;

    /**
     * Shadow rays per lamp and hit of the adaptive variants: 5 probe rays (the centre and a ring on the rim), the
     * other 4 only where the probes disagree. With 5 or fewer rays adaptive sampling has nothing to save.
     */
    static final int ADAPTIVE_SHADOW_RAYS = 9;

    static final Variant ADAPTIVE_GRID = new Variant(SamplingPattern.GRID, true);
    static final Variant ADAPTIVE_HALTON = new Variant(SamplingPattern.HALTON, true);

    private static final double LAMP_RADIUS = 10;

    @Override
    public String name() {
        return "street: anti-aliasing + soft shadows";
    }

    @Override
    public String slug() {
        return "street";
    }

    @Override
    public String sampleUnit() {
        return "camera rays per pixel = shadow rays per lamp";
    }

    @Override
    public List<Variant> variants() {
        return List.of(Variant.GRID, Variant.RANDOM, Variant.HALTON, ADAPTIVE_GRID, ADAPTIVE_HALTON);
    }

    /** Perfect squares up to 81, so that every GRID count is a full square grid and the baseline is measured itself. */
    @Override
    public int[] counts(int[] requested) {
        return new int[] {1, 4, 16, 36, BASELINE_SAMPLES};
    }

    /** Two fifths of the report's width (the street costs up to {@code 81 * 81} shadow rays per pixel and lamp). */
    @Override
    public int[] size(int width, int height) {
        int w = Math.max(8, width * 2 / 5);
        return new int[] {w, Math.max(5, w * 5 / 8)};
    }

    @Override
    public Camera camera(Variant variant, int samples, int width, int height) {
        SamplingConfig aa = new SamplingConfig(samples, TargetShape.RECTANGLE, variant.pattern());
        if (!variant.adaptive()) {
            return street(samples)
                    .camera(width, height)
                    .setSamplingConfig(aa)
                    .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(variant.pattern(), false))
                    .build();
        }
        boolean subdivide = variant.pattern() == SamplingPattern.GRID && samples > 1;
        return street(ADAPTIVE_SHADOW_RAYS)
                .camera(width, height)
                .setSamplingConfig(subdivide ? aa.adaptive(StreetScene.ADAPTIVE_THRESHOLD) : aa)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true))
                .build();
    }

    /**
     * 256 jittered camera rays per pixel, each with 16 jittered shadow rays per lamp drawn independently: 4,096
     * shadow rays per pixel and lamp, more than the 81 x 81 of the baseline, but spread over the whole disk.
     */
    @Override
    public Camera reference(int width, int height) {
        return street(16)
                .camera(width, height)
                .setSamplingConfig(new SamplingConfig(256, TargetShape.RECTANGLE, SamplingPattern.JITTERED))
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, false))
                .build();
    }

    @Override
    public double[] crop() {
        return new double[] {0.0, 0.35, 0.5, 0.65};
    }

    /**
     * The time the adaptive configuration needs to reach the RMSE of fixed GRID at 81 samples, interpolated on its
     * error-versus-time curve (log-log, between the two measurements around that error), as a fraction of the fixed
     * configuration's time.
     */
    @Override
    public String description() {
        return "Fixed variants: n camera rays per pixel and n shadow rays per lamp at every hit, in the named "
                + "pattern. Adaptive variants: n camera rays (adaptive grid: subdivision where colours differ by more "
                + "than " + StreetScene.ADAPTIVE_THRESHOLD + ", at most n; adaptive halton: exactly n) and adaptive "
                + "shadows of at most " + ADAPTIVE_SHADOW_RAYS + " jittered rays per lamp at every hit (5 probe rays, "
                + "the rest only where the probes disagree).";
    }

    @Override
    public String verdict(Map<String, List<Measurement>> byVariant) {
        Measurement baseline = byVariant.getOrDefault(Variant.GRID.label(), List.of()).stream()
                .filter(m -> m.samples() == BASELINE_SAMPLES)
                .findFirst()
                .orElse(null);
        if (baseline == null) return "";
        StringBuilder s = new StringBuilder(String.format(
                Locale.ROOT,
                "Fixed GRID %d + %d: RMSE %.3f in %.2f s.",
                BASELINE_SAMPLES,
                BASELINE_SAMPLES,
                baseline.rmse(),
                baseline.seconds()));
        for (Variant v : List.of(ADAPTIVE_GRID, ADAPTIVE_HALTON)) {
            List<Measurement> series = byVariant.get(v.label());
            if (series == null) continue;
            double seconds = timeToReach(series, baseline.rmse());
            s.append(
                    Double.isNaN(seconds)
                            ? String.format(
                                    Locale.ROOT,
                                    " %s does not reach that error at the counts measured (best RMSE %.3f).",
                                    v.label(),
                                    series.stream()
                                            .mapToDouble(Measurement::rmse)
                                            .min()
                                            .orElse(Double.NaN))
                            : String.format(
                                    Locale.ROOT,
                                    " %s reaches it in %.2f s, %.1f%% of the time (1/%.1f; target: at most 1/4).",
                                    v.label(),
                                    seconds,
                                    100 * seconds / baseline.seconds(),
                                    baseline.seconds() / seconds));
        }
        return s.append(System.lineSeparator()).toString();
    }

    /** The first time at which the series' RMSE falls to {@code target}, log-log interpolated; NaN if never. */
    static double timeToReach(List<Measurement> series, double target) {
        for (int i = 0; i < series.size(); i++) {
            Measurement m = series.get(i);
            if (m.rmse() <= target) {
                if (i == 0) return m.seconds();
                Measurement before = series.get(i - 1);
                double f = Math.log(before.rmse() / target) / Math.log(before.rmse() / m.rmse());
                return Math.exp(Math.log(before.seconds()) + f * Math.log(m.seconds() / before.seconds()));
            }
        }
        return Double.NaN;
    }

    private static StreetScene street(int shadowSamples) {
        return new StreetScene(shadowSamples > 1 ? StreetOptions.soft(LAMP_RADIUS, shadowSamples) : StreetOptions.HARD);
    }
}
