package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/**
 * A light that illuminates surfaces directly (everything but the ambient light). Positional lights may have a
 * radius: a disk of that radius facing the shaded point is sampled with {@link #getNumSamples()} shadow rays for
 * soft shadows.
 */
public interface LightSource {
    /** The intensity arriving at {@code point}, attenuation included. */
    Color getIntensity(Point point);

    /** The unit direction from the light toward {@code point}. */
    Vector getL(Point point);

    /** Distance from the light to {@code point}; infinite for directional lights. */
    double getDistance(Point point);

    /** The emitting position, or null for a directional light. */
    default Point getPosition() {
        return null;
    }

    /** Radius of the emitting disk; 0 for a point (hard shadows). */
    default double getRadius() {
        return 0;
    }

    /** Shadow rays per shading point for soft shadows; 1 for hard shadows. */
    default int getNumSamples() {
        return 1;
    }

    /** Whether this light casts soft shadows (a radius and more than one sample). */
    default boolean isSoft() {
        return getRadius() > 0 && getNumSamples() > 1;
    }
}
