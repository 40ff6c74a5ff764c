package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A point light, attenuated by {@code 1 / (kC + kL d + kQ d^2)}; with a radius and samples it is a disk light
 * that casts soft shadows.
 *
 * @param color RGB intensity (required)
 * @param position where it is (required)
 * @param kC constant attenuation (default 1)
 * @param kL linear attenuation (default 0)
 * @param kQ quadratic attenuation (default 0)
 * @param radius radius of the emitting disk (default 0: hard shadows)
 * @param samples shadow rays per shading point (default 1)
 */
@JsonPropertyOrder({"color", "position", "kC", "kL", "kQ", "radius", "samples", "range"})
public record PointLightDocument(
        Vec3 color, Vec3 position, Double kC, Double kL, Double kQ, Double radius, Integer samples, Double range)
        implements LightDocument {}
