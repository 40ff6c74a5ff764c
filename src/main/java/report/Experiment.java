package report;

import java.util.List;
import java.util.Map;
import renderer.Camera;

/**
 * A scene made to exercise one sampled effect, rendered at a given sample count with a given {@link Variant},
 * and once with so many samples that the result is the converged reference.
 */
public interface Experiment {
    /**
     * The effect's name, e.g. "anti-aliasing".
     *
     * @return the effect's human-readable name
     */
    String name();

    /**
     * A file-name-friendly key, e.g. "aa".
     *
     * @return the slug used in output file names
     */
    String slug();

    /**
     * What the sample count counts, e.g. "samples per pixel".
     *
     * @return the unit of the sample counts, for tables and charts
     */
    String sampleUnit();

    /**
     * The variants worth comparing on this effect.
     *
     * @return the variants, the first of which is used to warm up
     */
    List<Variant> variants();

    /**
     * The camera rendering the scene with {@code samples} of the effect spent as {@code variant}.
     *
     * @param variant the sampling pattern, fixed or adaptive
     * @param samples the number of samples of the effect, at least 1
     * @param width image width in pixels
     * @param height image height in pixels
     * @return a camera ready to render, not yet rendered
     */
    Camera camera(Variant variant, int samples, int width, int height);

    /**
     * The camera of the converged reference.
     *
     * @param width image width in pixels
     * @param height image height in pixels
     * @return a camera ready to render the reference, not yet rendered
     */
    Camera reference(int width, int height);

    /**
     * The region shown in the crops, as fractions of the image: x, y, width, height.
     *
     * @return four fractions in [0, 1]: left x, top y, width and height of the region
     */
    double[] crop();

    /**
     * The sample counts to measure, given the report's; by default the report's own.
     *
     * @param requested the report's sample counts
     * @return the counts this experiment measures
     */
    default int[] counts(int[] requested) {
        return requested;
    }

    /**
     * The image size to render, given the report's {@code width x height}; by default the report's own.
     *
     * @param width the report's image width in pixels
     * @param height the report's image height in pixels
     * @return the width and height to render, in that order
     */
    default int[] size(int width, int height) {
        return new int[] {width, height};
    }

    /**
     * What the variants mean, when the labels alone do not say it; empty by default.
     *
     * @return the description in Markdown, or the empty string
     */
    default String description() {
        return "";
    }

    /**
     * A sentence on the experiment's target, from its measurements; empty when it has none.
     *
     * @param byVariant the measurements of each variant, keyed by its label
     * @return the sentence in Markdown, or the empty string
     */
    default String verdict(Map<String, List<Measurement>> byVariant) {
        return "";
    }

    /**
     * The camera for progressive sampling (a target error or a time budget is set on it): by default the HALTON
     * variant with 2 samples of the effect per camera sample (2 shadow rays per light, 2 lens or glossy rays; one
     * would be the centre of the light or lens), so that each pass refines the effect together with the pixel.
     *
     * @param width image width in pixels
     * @param height image height in pixels
     * @return a camera ready for {@link renderer.Camera#setProgressive}, not yet rendered
     */
    default Camera progressive(int width, int height) {
        return camera(Variant.HALTON, 2, width, height);
    }
}
