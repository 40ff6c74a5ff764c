package lighting;

import primitives.Color;
import primitives.Double3;
import primitives.Util;

/** Uniform light reaching every surface regardless of geometry: the intensity times an attenuation kA. */
public final class AmbientLight {
    /** No ambient light. */
    public static final AmbientLight NONE = new AmbientLight(Color.BLACK);

    private final Color intensity;

    public AmbientLight(Color intensity, Double3 kA) {
        Util.requireNonNull(intensity, "ambient intensity");
        Util.requireNonNull(kA, "ambient kA").requireInRange(0, Double.MAX_VALUE, "ambient kA");
        this.intensity = intensity.scale(kA);
    }

    public AmbientLight(Color intensity, double kA) {
        this(intensity, new Double3(kA));
    }

    public AmbientLight(Color intensity) {
        this(intensity, Double3.ONE);
    }

    public Color getIntensity() {
        return intensity;
    }
}
