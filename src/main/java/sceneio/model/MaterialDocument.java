package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A Phong material with mirror reflection and refraction; every field is optional (defaults: kA 1, the rest 0,
 * indexOfRefraction 1). Coefficients are a number or [r, g, b], each zero or positive.
 *
 * @param kA ambient
 * @param kD diffuse
 * @param kS specular
 * @param shininess specular exponent, an integer >= 0
 * @param kR mirror reflection
 * @param kT transparency
 * @param indexOfRefraction 0.001 to 1000
 * @param roughness 0 (ideal mirror and clear glass) to 1
 * @param kDMap an image whose colour at the hit point multiplies kD (meshes with texture coordinates), or null
 */
@JsonPropertyOrder({"kA", "kD", "kS", "shininess", "kR", "kT", "indexOfRefraction", "roughness", "kDMap"})
public record MaterialDocument(
        Coefficient kA,
        Coefficient kD,
        Coefficient kS,
        Integer shininess,
        Coefficient kR,
        Coefficient kT,
        Double indexOfRefraction,
        Double roughness,
        TextureDocument kDMap) {
    /**
     * A material without a texture.
     *
     * @param kA ambient
     * @param kD diffuse
     * @param kS specular
     * @param shininess specular exponent, an integer >= 0
     * @param kR mirror reflection
     * @param kT transparency
     * @param indexOfRefraction 0.001 to 1000
     * @param roughness 0 (ideal mirror and clear glass) to 1
     */
    public MaterialDocument(
            Coefficient kA,
            Coefficient kD,
            Coefficient kS,
            Integer shininess,
            Coefficient kR,
            Coefficient kT,
            Double indexOfRefraction,
            Double roughness) {
        this(kA, kD, kS, shininess, kR, kT, indexOfRefraction, roughness, null);
    }
}
