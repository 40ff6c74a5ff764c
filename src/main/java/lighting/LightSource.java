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
    /**
     * The intensity arriving at {@code point}, attenuation included.
     *
     * @param point the shaded point
     * @return the intensity arriving there, black where the light does not reach
     */
    Color getIntensity(Point point);

    /**
     * The unit direction from the light toward {@code point}.
     *
     * @param point the shaded point
     * @return the unit vector from the light toward {@code point}
     */
    Vector getL(Point point);

    /**
     * Distance from the light to {@code point}; infinite for directional lights.
     *
     * @param point the shaded point
     * @return the distance in scene units, {@link Double#POSITIVE_INFINITY} for directional lights
     */
    double getDistance(Point point);

    /**
     * The emitting position, or null for a directional light.
     *
     * @return the light's position, or null for a directional light
     */
    default Point getPosition() {
        return null;
    }

    /**
     * Radius of the emitting disk; 0 for a point (hard shadows).
     *
     * @return the radius in scene units, 0 for a point
     */
    default double getRadius() {
        return 0;
    }

    /**
     * Shadow rays per shading point for soft shadows; 1 for hard shadows.
     *
     * @return the number of shadow rays, at least 1
     */
    default int getNumSamples() {
        return 1;
    }

    /**
     * Fills {@code out} with what this light gives the point (x, y, z): {@link #getDistance}, then, unless that is
     * 0, {@link #getL} and {@link #getIntensity}, with the same values. The built-in lights override it to allocate
     * nothing; this default goes through the methods above (a light of your own works unchanged).
     *
     * @param x the point's x coordinate
     * @param y the point's y coordinate
     * @param z the point's z coordinate
     * @param out the sample to fill; reused by the caller
     */
    default void illuminate(double x, double y, double z, LightSample out) {
        Point p = new Point(x, y, z);
        out.distance = getDistance(p);
        if (out.distance == 0) return;
        Vector l = getL(p);
        out.lx = l.x;
        out.ly = l.y;
        out.lz = l.z;
        Color c = getIntensity(p);
        out.r = c.getR();
        out.g = c.getG();
        out.b = c.getB();
    }

    /**
     * Whether this light casts soft shadows (a radius and more than one sample).
     *
     * @return true when the light has a positive radius and more than one sample
     */
    default boolean isSoft() {
        return getRadius() > 0 && getNumSamples() > 1;
    }
}
