package report;

import java.util.List;
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
}
