package lighting;

import primitives.Color;
import primitives.Double3;
import primitives.Util;

/** Uniform light reaching every surface regardless of geometry: the intensity times an attenuation kA. */
public final class AmbientLight {
    /** No ambient light. */
    public static final AmbientLight NONE = new AmbientLight(Color.BLACK);

    private final Color intensity;

    /**
     * An ambient light of {@code intensity} attenuated per channel by {@code kA}.
     *
     * @param intensity the light's colour and strength; not null
     * @param kA the attenuation per channel, each at least 0; not null
     * @throws IllegalArgumentException if an argument is null or a channel of {@code kA} is negative
     */
    public AmbientLight(Color intensity, Double3 kA) {
        Util.requireNonNull(intensity, "ambient intensity");
        Util.requireNonNull(kA, "ambient kA").requireInRange(0, Double.MAX_VALUE, "ambient kA");
        this.intensity = intensity.scale(kA);
    }

    /**
     * An ambient light of {@code intensity} attenuated by {@code kA} in every channel.
     *
     * @param intensity the light's colour and strength; not null
     * @param kA the attenuation of all three channels, at least 0
     * @throws IllegalArgumentException if {@code intensity} is null or {@code kA} is negative
     */
    public AmbientLight(Color intensity, double kA) {
        this(intensity, new Double3(kA));
    }

    /**
     * An ambient light of {@code intensity}, not attenuated (kA = 1).
     *
     * @param intensity the light's colour and strength; not null
     */
    public AmbientLight(Color intensity) {
        this(intensity, Double3.ONE);
    }

    /**
     * The ambient intensity reaching every surface.
     *
     * @return the intensity times kA, never null
     */
    public Color getIntensity() {
        return intensity;
    }
}
