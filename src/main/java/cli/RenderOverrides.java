package cli;

import java.io.Serializable;
import picocli.CommandLine.Option;
import primitives.Limits;
import sceneio.model.CameraDocument;
import sceneio.model.RenderDocument;
import sceneio.model.SamplingDocument;
import sceneio.model.SceneDocument;

/**
 * The options that change a scene file's render settings ({@code --bvh}, {@code --samples}, {@code --width},
 * {@code --height}), as a picocli mixin shared by the commands that render scene files. They are written into the
 * scene document, so the loader validates them like the file. Serializable because a distributed render applies
 * the same overrides to the scene on every worker.
 */
public final class RenderOverrides implements Serializable {
    private static final long serialVersionUID = 1L;

    /** An on/off option value. */
    public enum Switch {
        /** The option is on. */
        ON,
        /** The option is off. */
        OFF
    }

    /** {@code --bvh}: whether to search with the BVH, or null to keep the scene's setting. */
    @Option(names = "--bvh", paramLabel = "on|off", description = "use the BVH (default: the scene's, else on)")
    private Switch bvh;

    /** {@code --samples}: anti-aliasing rays per pixel, or null to keep the scene's setting. */
    @Option(names = "--samples", paramLabel = "N", description = "anti-aliasing rays per pixel (1 = off)")
    private Integer samples;

    /** {@code --width}: the image width in pixels, or null to keep the scene's setting. */
    @Option(
            names = "--width",
            paramLabel = "W",
            description = "image width; alone, the height follows the scene's aspect ratio")
    private Integer width;

    /** {@code --height}: the image height in pixels, or null to keep the scene's setting. */
    @Option(
            names = "--height",
            paramLabel = "H",
            description = "image height; alone, the width follows the scene's aspect ratio")
    private Integer height;

    /** {@code --light-cutoff}: display steps of direct light that may be left out, or null to keep the scene's. */
    @Option(
            names = "--light-cutoff",
            paramLabel = "STEPS",
            description = "display steps of direct light a camera sample may leave out by not sampling lights too"
                    + " faint to matter, 0 (exact) to 255 (default: the scene's, else 0.5)")
    private Double lightCutoff;

    /** {@code --target-error}: progressive sampling to this image RMSE, or null to keep the scene's sampling. */
    @Option(
            names = "--target-error",
            paramLabel = "E",
            description = "sample progressively until the image's estimated RMSE is at most E display steps (0..255"
                    + " scale); replaces the fixed anti-aliasing and the scene's target or budget")
    private Double targetError;

    /** {@code --time-budget}: progressive sampling for this many seconds, or null to keep the scene's sampling. */
    @Option(
            names = "--time-budget",
            paramLabel = "S",
            description = "sample progressively for S seconds of wall time, where the estimated error is highest;"
                    + " replaces the fixed anti-aliasing and the scene's target or budget")
    private Double timeBudget;

    /** No overrides: the scene file's settings (picocli fills the options of a mixin it creates this way). */
    public RenderOverrides() {}

    /**
     * These overrides; null leaves the scene's setting.
     *
     * @param width the image width in pixels, or null
     * @param height the image height in pixels, or null
     * @param samples anti-aliasing rays per pixel, or null
     * @param bvh true for the BVH, false for brute force, or null
     * @return new overrides with no light cutoff override
     */
    public static RenderOverrides of(Integer width, Integer height, Integer samples, Boolean bvh) {
        RenderOverrides o = new RenderOverrides();
        o.width = width;
        o.height = height;
        o.samples = samples;
        o.bvh = bvh == null ? null : bvh ? Switch.ON : Switch.OFF;
        return o;
    }

    /**
     * Rejects values no scene could take, naming the option.
     *
     * @throws BadInputException if a count or size is below 1, the samples exceed {@link Limits#MAX_SAMPLES} or the
     *     light cutoff is outside [0, 255]
     */
    public void check() throws BadInputException {
        checkRange("--samples", samples, Limits.MAX_SAMPLES);
        checkRange("--width", width, MAX_SIDE);
        checkRange("--height", height, MAX_SIDE);
        if (lightCutoff != null && !(lightCutoff >= 0 && lightCutoff <= 255)) {
            throw new BadInputException("--light-cutoff must be in [0, 255] display steps, but was " + lightCutoff);
        }
        if (targetError != null && timeBudget != null) {
            throw new BadInputException("give either --target-error or --time-budget, not both");
        }
        if (targetError != null && !(targetError > 0 && targetError <= 255)) {
            throw new BadInputException("--target-error must be in (0, 255] display steps, but was " + targetError);
        }
        if (timeBudget != null && !(timeBudget > 0 && timeBudget <= 1e7)) {
            throw new BadInputException("--time-budget must be in (0, 1e7] seconds, but was " + timeBudget);
        }
    }

    /** Longest image side: an image holds at most {@link Limits#MAX_PIXELS} pixels (the loader checks the product). */
    static final int MAX_SIDE = Limits.MAX_PIXELS;

    static void checkRange(String option, Integer value, int max) throws BadInputException {
        if (value != null && (value < 1 || value > max)) {
            throw new BadInputException(option + " must be in [1, " + max + "], but was " + value);
        }
    }

    /**
     * The document with these overrides. One of width and height keeps the scene's aspect ratio; both with another
     * ratio keep the view plane width and square pixels.
     *
     * @param d the scene document as read
     * @return a document with the overridden settings, or {@code d} itself when it has no render section
     */
    public SceneDocument apply(SceneDocument d) {
        RenderDocument r = d.render();
        if (r == null) return d; // the loader reports the missing section
        if (bvh != null) r = r.withBvh(bvh == Switch.ON);
        if (lightCutoff != null) r = r.withLightCutoff(lightCutoff);
        if (targetError != null || timeBudget != null) r = r.withProgressive(targetError, timeBudget);
        if (samples != null) {
            SamplingDocument aa = r.antiAliasing();
            r = r.withAntiAliasing(
                    aa == null
                            ? new SamplingDocument(samples, null, null, null)
                            : new SamplingDocument(samples, aa.shape(), aa.pattern(), aa.adaptiveThreshold()));
        }
        CameraDocument camera = d.camera();
        if (width != null || height != null) {
            if (r.width() == null || r.height() == null || r.width() < 1 || r.height() < 1) {
                return d.withRender(
                        r.withSize(width != null ? width : r.width(), height != null ? height : r.height()));
            }
            double aspect = (double) r.width() / r.height();
            // Clamped to int: a side beyond 2^31 is reported by the loader as an image too large, not wrapped.
            int w = width != null ? width : (int) Math.min(Integer.MAX_VALUE, Math.max(1, Math.round(height * aspect)));
            int h = height != null
                    ? height
                    : (int) Math.min(Integer.MAX_VALUE, Math.max(1, Math.round(width / aspect)));
            r = r.withSize(w, h);
            // Both given with another aspect ratio: keep the view plane width and square pixels.
            if (width != null && height != null && camera != null && camera.vpWidth() != null) {
                camera = camera.withVpHeight(camera.vpWidth() * h / w);
            }
        }
        return d.withRender(r).withCamera(camera);
    }
}
