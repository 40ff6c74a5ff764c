package report;

import java.util.List;
import java.util.Map;
import renderer.Camera;

/**
 * A scene made to exercise one sampled effect, rendered at a given sample count with a given {@link Variant},
 * and once with so many samples that the result is the converged reference.
 */
public interface Experiment {
    /** The effect's name, e.g. "anti-aliasing". */
    String name();

    /** A file-name-friendly key, e.g. "aa". */
    String slug();

    /** What the sample count counts, e.g. "samples per pixel". */
    String sampleUnit();

    /** The variants worth comparing on this effect. */
    List<Variant> variants();

    /** The camera rendering the scene with {@code samples} of the effect spent as {@code variant}. */
    Camera camera(Variant variant, int samples, int width, int height);

    /** The camera of the converged reference. */
    Camera reference(int width, int height);

    /** The region shown in the crops, as fractions of the image: x, y, width, height. */
    double[] crop();

    /** The sample counts to measure, given the report's; by default the report's own. */
    default int[] counts(int[] requested) {
        return requested;
    }

    /** The image size to render, given the report's {@code width x height}; by default the report's own. */
    default int[] size(int width, int height) {
        return new int[] {width, height};
    }

    /** What the variants mean, when the labels alone do not say it; empty by default. */
    default String description() {
        return "";
    }

    /** A sentence on the experiment's target, from its measurements; empty when it has none. */
    default String verdict(Map<String, List<Measurement>> byVariant) {
        return "";
    }
}
