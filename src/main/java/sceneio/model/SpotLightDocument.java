package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A point light shining along a direction, its beam narrowed by the exponent {@code narrowBeam}.
 *
 * @param color RGB intensity (required)
 * @param position where it is (required)
 * @param direction where it shines (required, non-zero)
 * @param narrowBeam beam exponent, >= 1 (default 1)
 * @param kC constant attenuation (default 1)
 * @param kL linear attenuation (default 0)
 * @param kQ quadratic attenuation (default 0)
 * @param radius radius of the emitting disk (default 0)
 * @param samples shadow rays per shading point (default 1)
 */
@JsonPropertyOrder({"color", "position", "direction", "narrowBeam", "kC", "kL", "kQ", "radius", "samples", "range"})
public record SpotLightDocument(
        Vec3 color,
        Vec3 position,
        Vec3 direction,
        Double narrowBeam,
        Double kC,
        Double kL,
        Double kQ,
        Double radius,
        Integer samples,
        Double range)
        implements LightDocument {}
