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

    public Double3 getKa() {
        return kA;
    }

    public Double3 getKd() {
        return kD;
    }

    public Double3 getKs() {
        return kS;
    }

    public Double3 getKr() {
        return kR;
    }

    public Double3 getKt() {
        return kT;
    }

    public int getShininess() {
        return shininess;
    }

    public double getIndexOfRefraction() {
        return indexOfRefraction;
    }

    /** Spread of reflected and refracted rays, 0 (ideal mirror and clear glass) to 1 (very rough). */
    public double getRoughness() {
        return roughness;
    }

    public Material setKa(Double3 kA) {
        this.kA = coefficient(kA, "kA");
        return this;
    }

    public Material setKa(double kA) {
        return setKa(new Double3(kA));
    }

    public Material setKd(Double3 kD) {
        this.kD = coefficient(kD, "kD");
        return this;
    }

    public Material setKd(double kD) {
        return setKd(new Double3(kD));
    }

    public Material setKs(Double3 kS) {
        this.kS = coefficient(kS, "kS");
        return this;
    }

    public Material setKs(double kS) {
        return setKs(new Double3(kS));
    }

    public Material setKr(Double3 kR) {
        this.kR = coefficient(kR, "kR");
        return this;
    }

    public Material setKr(double kR) {
        return setKr(new Double3(kR));
    }

    public Material setKt(Double3 kT) {
        this.kT = coefficient(kT, "kT");
        return this;
    }

    public Material setKt(double kT) {
        return setKt(new Double3(kT));
    }

    public Material setShininess(int shininess) {
        if (shininess < 0) {
            throw new IllegalArgumentException("shininess must be >= 0, but was " + shininess);
        }
        this.shininess = shininess;
        return this;
    }

    public Material setIndexOfRefraction(double indexOfRefraction) {
        if (!(indexOfRefraction >= 1e-3 && indexOfRefraction <= 1e3)) {
            throw new IllegalArgumentException(
                    "indexOfRefraction must be in [0.001, 1000], but was " + indexOfRefraction);
        }
        this.indexOfRefraction = indexOfRefraction;
        return this;
    }

    public Material setRoughness(double roughness) {
        this.roughness = Util.requireInRange(roughness, 0, 1, "roughness");
        return this;
    }

    /** Whether this material reflects any light as a mirror. */
    public boolean isReflective() {
        return !kR.isZero();
    }

    /** Whether this material lets any light through. */
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
                + kT + ", ior=" + indexOfRefraction + ", roughness=" + roughness + "}";
    }
}
