package primitives;

/**
 * The optical properties of a surface for Phong shading plus mirror reflection and refraction: ambient kA,
 * diffuse kD, specular kS with its shininess, reflection kR, transparency kT with the index of refraction, and a
 * roughness that spreads reflected and refracted rays into a cone (glossy and frosted surfaces).
 *
 * <p>Fluent setters return this material so scenes read naturally; every value is validated. An index of
 * refraction of 1.0 (the default) makes transparency go straight through.
 */
public final class Material {
    private Double3 kA = Double3.ONE;
    private Double3 kD = Double3.ZERO;
    private Double3 kS = Double3.ZERO;
    private Double3 kR = Double3.ZERO;
    private Double3 kT = Double3.ZERO;
    private int shininess = 0;
    private double indexOfRefraction = 1.0;
    private double roughness = 0.0;
    /** Multiplies kD per hit point when set (MTL's map_Kd); null for a uniform kD. */
    private Texture kDMap;

    /**
     * The ambient coefficient kA per channel.
     *
     * @return kA, default (1, 1, 1), each channel at least 0
     */
    public Double3 getKa() {
        return kA;
    }

    /**
     * The diffuse coefficient kD per channel.
     *
     * @return kD, default 0, each channel at least 0
     */
    public Double3 getKd() {
        return kD;
    }

    /**
     * The specular coefficient kS per channel.
     *
     * @return kS, default 0, each channel at least 0
     */
    public Double3 getKs() {
        return kS;
    }

    /**
     * The mirror reflection coefficient kR per channel.
     *
     * @return kR, default 0, each channel at least 0
     */
    public Double3 getKr() {
        return kR;
    }

    /**
     * The transparency coefficient kT per channel.
     *
     * @return kT, default 0, each channel at least 0
     */
    public Double3 getKt() {
        return kT;
    }

    /**
     * The Phong exponent of the specular highlight: larger is sharper.
     *
     * @return the shininess, at least 0 (default 0)
     */
    public int getShininess() {
        return shininess;
    }

    /**
     * The index of refraction of the material's inside, relative to the outside.
     *
     * @return the index, in [0.001, 1000] (default 1: no bending)
     */
    public double getIndexOfRefraction() {
        return indexOfRefraction;
    }

    /**
     * Spread of reflected and refracted rays, 0 (ideal mirror and clear glass) to 1 (very rough).
     *
     * @return the roughness, in [0, 1]
     */
    public double getRoughness() {
        return roughness;
    }

    /**
     * Sets the ambient coefficient per channel and returns this material.
     *
     * @param kA the coefficient of each channel, finite and at least 0; not null
     * @return this material
     * @throws IllegalArgumentException if {@code kA} is null or a channel is negative or not finite
     */
    public Material setKa(Double3 kA) {
        this.kA = coefficient(kA, "kA");
        return this;
    }

    /**
     * Sets the ambient coefficient of all three channels and returns this material.
     *
     * @param kA the coefficient, finite and at least 0
     * @return this material
     * @throws IllegalArgumentException if {@code kA} is negative or not finite
     */
    public Material setKa(double kA) {
        return setKa(new Double3(kA));
    }

    /**
     * Sets the diffuse coefficient per channel and returns this material.
     *
     * @param kD the coefficient of each channel, finite and at least 0; not null
     * @return this material
     * @throws IllegalArgumentException if {@code kD} is null or a channel is negative or not finite
     */
    public Material setKd(Double3 kD) {
        this.kD = coefficient(kD, "kD");
        return this;
    }

    /**
     * Sets the diffuse coefficient of all three channels and returns this material.
     *
     * @param kD the coefficient, finite and at least 0
     * @return this material
     * @throws IllegalArgumentException if {@code kD} is negative or not finite
     */
    public Material setKd(double kD) {
        return setKd(new Double3(kD));
    }

    /**
     * Sets the specular coefficient per channel and returns this material.
     *
     * @param kS the coefficient of each channel, finite and at least 0; not null
     * @return this material
     * @throws IllegalArgumentException if {@code kS} is null or a channel is negative or not finite
     */
    public Material setKs(Double3 kS) {
        this.kS = coefficient(kS, "kS");
        return this;
    }

    /**
     * Sets the specular coefficient of all three channels and returns this material.
     *
     * @param kS the coefficient, finite and at least 0
     * @return this material
     * @throws IllegalArgumentException if {@code kS} is negative or not finite
     */
    public Material setKs(double kS) {
        return setKs(new Double3(kS));
    }

    /**
     * Sets the mirror reflection coefficient per channel and returns this material.
     *
     * @param kR the coefficient of each channel, finite and at least 0; not null
     * @return this material
     * @throws IllegalArgumentException if {@code kR} is null or a channel is negative or not finite
     */
    public Material setKr(Double3 kR) {
        this.kR = coefficient(kR, "kR");
        return this;
    }

    /**
     * Sets the mirror reflection coefficient of all three channels and returns this material.
     *
     * @param kR the coefficient, finite and at least 0
     * @return this material
     * @throws IllegalArgumentException if {@code kR} is negative or not finite
     */
    public Material setKr(double kR) {
        return setKr(new Double3(kR));
    }

    /**
     * Sets the transparency coefficient per channel and returns this material.
     *
     * @param kT the coefficient of each channel, finite and at least 0; not null
     * @return this material
     * @throws IllegalArgumentException if {@code kT} is null or a channel is negative or not finite
     */
    public Material setKt(Double3 kT) {
        this.kT = coefficient(kT, "kT");
        return this;
    }

    /**
     * Sets the transparency coefficient of all three channels and returns this material.
     *
     * @param kT the coefficient, finite and at least 0
     * @return this material
     * @throws IllegalArgumentException if {@code kT} is negative or not finite
     */
    public Material setKt(double kT) {
        return setKt(new Double3(kT));
    }

    /**
     * Sets the Phong exponent and returns this material.
     *
     * @param shininess the exponent of the specular highlight, at least 0
     * @return this material
     * @throws IllegalArgumentException if {@code shininess} is negative
     */
    public Material setShininess(int shininess) {
        if (shininess < 0) {
            throw new IllegalArgumentException("shininess must be >= 0, but was " + shininess);
        }
        this.shininess = shininess;
        return this;
    }

    /**
     * Sets the index of refraction and returns this material.
     *
     * @param indexOfRefraction the index of the inside relative to the outside, in [0.001, 1000]
     * @return this material
     * @throws IllegalArgumentException if the index is outside [0.001, 1000] or NaN
     */
    public Material setIndexOfRefraction(double indexOfRefraction) {
        if (!(indexOfRefraction >= 1e-3 && indexOfRefraction <= 1e3)) {
            throw new IllegalArgumentException(
                    "indexOfRefraction must be in [0.001, 1000], but was " + indexOfRefraction);
        }
        this.indexOfRefraction = indexOfRefraction;
        return this;
    }

    /**
     * Sets the roughness and returns this material.
     *
     * @param roughness the spread of reflected and refracted rays, in [0, 1]
     * @return this material
     * @throws IllegalArgumentException if {@code roughness} is outside [0, 1] or NaN
     */
    public Material setRoughness(double roughness) {
        this.roughness = Util.requireInRange(roughness, 0, 1, "roughness");
        return this;
    }

    /**
     * The texture that multiplies kD at each hit point (the diffuse colour map), or null.
     *
     * @return the diffuse map, or null when kD is uniform
     */
    public Texture getKdMap() {
        return kDMap;
    }

    /**
     * Sets the texture whose value at the hit point's texture coordinates multiplies kD per channel (as MTL's
     * {@code map_Kd} multiplies {@code Kd}), or removes it with null, and returns this material. Only geometries with
     * texture coordinates (meshes read with OBJ {@code vt}) vary across the map; others see its value at (0, 0).
     *
     * @param map the diffuse map, or null for a uniform kD
     * @return this material
     */
    public Material setKdMap(Texture map) {
        this.kDMap = map;
        return this;
    }

    /**
     * Whether this material reflects any light as a mirror.
     *
     * @return true when kR is not zero
     */
    public boolean isReflective() {
        return !kR.isZero();
    }

    /**
     * Whether this material lets any light through.
     *
     * @return true when kT is not zero
     */
    public boolean isTransparent() {
        return !kT.isZero();
    }

    private static Double3 coefficient(Double3 value, String name) {
        Util.requireNonNull(value, name);
        return value.requireInRange(0, Double.MAX_VALUE, name);
    }

    @Override
    public String toString() {
        return "Material{kA=" + kA + ", kD=" + kD + ", kS=" + kS + ", shininess=" + shininess + ", kR=" + kR + ", kT="
                + kT + ", ior=" + indexOfRefraction + ", roughness=" + roughness
                + (kDMap == null ? "" : ", kDMap=" + kDMap) + "}";
    }
}
