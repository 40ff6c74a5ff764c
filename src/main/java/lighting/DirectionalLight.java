package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Util;
import primitives.Vector;

/** Light from infinitely far away along one direction (the sun, the moon): no attenuation, hard shadows. */
public final class DirectionalLight implements LightSource {
    private final Color intensity;
    private final Vector direction;

    /**
     * A light of constant {@code intensity} shining along {@code direction}.
     *
     * @param intensity the light's colour and strength, the same at every point; not null
     * @param direction the direction the light travels, from the light toward the scene; any length, normalized here
     */
    public DirectionalLight(Color intensity, Vector direction) {
        this.intensity = Util.requireNonNull(intensity, "light intensity");
        this.direction = Util.requireNonNull(direction, "light direction").normalize();
    }

    @Override
    public Color getIntensity(Point point) {
        return intensity;
    }

    @Override
    public Vector getL(Point point) {
        return direction;
    }

    @Override
    public double getDistance(Point point) {
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public void illuminate(double x, double y, double z, LightSample out) {
        out.distance = Double.POSITIVE_INFINITY;
        out.lx = direction.x;
        out.ly = direction.y;
        out.lz = direction.z;
        out.r = intensity.getR();
        out.g = intensity.getG();
        out.b = intensity.getB();
    }

    /**
     * The direction the light travels.
     *
     * @return the unit direction from the light toward the scene
     */
    public Vector getDirection() {
        return direction;
    }
}
