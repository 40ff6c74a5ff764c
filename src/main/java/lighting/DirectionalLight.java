package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Util;
import primitives.Vector;

/** Light from infinitely far away along one direction (the sun, the moon): no attenuation, hard shadows. */
public final class DirectionalLight implements LightSource {
    private final Color intensity;
    private final Vector direction;

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

    public Vector getDirection() {
        return direction;
    }
}
