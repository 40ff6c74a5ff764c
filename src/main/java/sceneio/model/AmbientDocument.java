package sceneio.model;

/**
 * The ambient light: a colour scaled by {@code kA}.
 *
 * @param color RGB intensity, 0..255 per channel (required)
 * @param kA attenuation, a number or [r, g, b] (default 1)
 */
public record AmbientDocument(Vec3 color, Coefficient kA) {}
