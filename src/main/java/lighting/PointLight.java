package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Util;
import primitives.Vector;

/**
 * Light from a position, attenuated by {@code 1 / (kC + kL d + kQ d^2)}. With {@link #setRadius} and
 * {@link #setNumSamples} it becomes a disk light that casts soft shadows.
 */
public class PointLight implements LightSource {
    private final Color intensity;
    private final Point position;
    private double kC = 1, kL = 0, kQ = 0;
    private double radius = 0;
    private int numSamples = 1;
    private double range = Double.POSITIVE_INFINITY;

    public PointLight(Color intensity, Point position) {
        this.intensity = Util.requireNonNull(intensity, "light intensity");
        this.position = Util.requireNonNull(position, "light position");
    }

    public PointLight setKc(double kC) {
        this.kC = Util.requireNonNegative(kC, "kC");
        return this;
    }

    public PointLight setKl(double kL) {
        this.kL = Util.requireNonNegative(kL, "kL");
        return this;
    }

    public PointLight setKq(double kQ) {
        this.kQ = Util.requireNonNegative(kQ, "kQ");
        return this;
    }

    /** Radius of the emitting disk (0 = a point: hard shadows). */
    public PointLight setRadius(double radius) {
        this.radius = Util.requireNonNegative(radius, "light radius");
        return this;
    }

    /** Shadow rays per shading point when the radius is positive. */
    public PointLight setNumSamples(int numSamples) {
        if (numSamples < 1) {
            throw new IllegalArgumentException("light numSamples must be >= 1, but was " + numSamples);
        }
        this.numSamples = numSamples;
        return this;
    }

    /**
     * Distance beyond which the light contributes nothing (a hard cut-off, as lights in games and modelling tools
     * have); infinite by default. Points beyond it cost no shadow rays.
     */
    public PointLight setRange(double range) {
        if (!(range > 0)) throw new IllegalArgumentException("light range must be positive, but was " + range);
        this.range = range;
        return this;
    }

    public double getRange() {
        return range;
    }

    @Override
    public Color getIntensity(Point point) {
        double d = getDistance(point);
        if (d > range) return Color.BLACK;
        double attenuation = kC + kL * d + kQ * d * d;
        if (!(attenuation > 0)) {
            throw new IllegalStateException("light attenuation kC + kL d + kQ d^2 must be positive, but was "
                    + attenuation + " at distance " + d + " (kC=" + kC + ", kL=" + kL + ", kQ=" + kQ + ")");
        }
        return intensity.scale(1 / attenuation);
    }

    @Override
    public Vector getL(Point point) {
        return point.subtract(position).normalize();
    }

    @Override
    public double getDistance(Point point) {
        return point.distance(position);
    }

    @Override
    public Point getPosition() {
        return position;
    }

    @Override
    public double getRadius() {
        return radius;
    }

    @Override
    public int getNumSamples() {
        return numSamples;
    }

    /** The unattenuated intensity. */
    public Color getBaseIntensity() {
        return intensity;
    }

    public double getKc() {
        return kC;
    }

    public double getKl() {
        return kL;
    }

    public double getKq() {
        return kQ;
    }
}
