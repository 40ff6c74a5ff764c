package lighting;

import primitives.Color;
import primitives.Limits;
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

    /**
     * A point light at {@code position} with no attenuation (kC = 1, kL = kQ = 0), radius 0 and infinite range.
     *
     * @param intensity the light's colour and strength at the position; not null
     * @param position where the light is; not null
     */
    public PointLight(Color intensity, Point position) {
        this.intensity = Util.requireNonNull(intensity, "light intensity");
        this.position = Util.requireNonNull(position, "light position");
    }

    /**
     * Sets the constant attenuation factor and returns this light.
     *
     * @param kC the constant term of {@code kC + kL d + kQ d^2}, at least 0
     * @return this light
     */
    public PointLight setKc(double kC) {
        this.kC = Util.requireNonNegative(kC, "kC");
        return this;
    }

    /**
     * Sets the linear attenuation factor and returns this light.
     *
     * @param kL the linear term of {@code kC + kL d + kQ d^2}, at least 0
     * @return this light
     */
    public PointLight setKl(double kL) {
        this.kL = Util.requireNonNegative(kL, "kL");
        return this;
    }

    /**
     * Sets the quadratic attenuation factor and returns this light.
     *
     * @param kQ the quadratic term of {@code kC + kL d + kQ d^2}, at least 0
     * @return this light
     */
    public PointLight setKq(double kQ) {
        this.kQ = Util.requireNonNegative(kQ, "kQ");
        return this;
    }

    /**
     * Radius of the emitting disk (0 = a point: hard shadows).
     *
     * @param radius the disk radius in scene units, at least 0
     * @return this light
     */
    public PointLight setRadius(double radius) {
        this.radius = Util.requireNonNegative(radius, "light radius");
        return this;
    }

    /**
     * Shadow rays per shading point when the radius is positive, 1 to {@link Limits#MAX_SAMPLES} (the
     * limit of anti-aliasing too).
     *
     * @param numSamples the number of shadow rays, 1 to {@link Limits#MAX_SAMPLES}
     * @return this light
     * @throws IllegalArgumentException if {@code numSamples} is out of range
     */
    public PointLight setNumSamples(int numSamples) {
        if (numSamples < 1 || numSamples > Limits.MAX_SAMPLES) {
            throw new IllegalArgumentException(
                    "light numSamples must be in [1, " + Limits.MAX_SAMPLES + "], but was " + numSamples);
        }
        this.numSamples = numSamples;
        return this;
    }

    /**
     * Distance beyond which the light contributes nothing (a hard cut-off, as lights in games and modelling tools
     * have); infinite by default. Points beyond it cost no shadow rays.
     *
     * @param range the distance in scene units, positive (may be infinite)
     * @return this light
     * @throws IllegalArgumentException if {@code range} is not positive
     */
    public PointLight setRange(double range) {
        if (!(range > 0)) throw new IllegalArgumentException("light range must be positive, but was " + range);
        this.range = range;
        return this;
    }

    /**
     * The distance beyond which the light contributes nothing.
     *
     * @return the range in scene units, {@link Double#POSITIVE_INFINITY} unless set
     */
    public double getRange() {
        return range;
    }

    @Override
    public Color getIntensity(Point point) {
        double d = getDistance(point);
        if (d > range) return Color.BLACK;
        return intensity.scale(1 / attenuation(d));
    }

    /**
     * {@link #getDistance}, {@link #getL} and {@link #getIntensity} at once, with the same arithmetic and so the
     * same values, allocating nothing.
     */
    @Override
    public void illuminate(double x, double y, double z, LightSample out) {
        double dx = x - position.x, dy = y - position.y, dz = z - position.z;
        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        out.distance = d;
        if (d == 0) return;
        // Vector.normalize's arithmetic.
        double unit = Vector.unitFactor(dx, dy, dz);
        if (unit > 0) {
            out.lx = dx * unit;
            out.ly = dy * unit;
            out.lz = dz * unit;
        } else {
            out.lx = Vector.unitComponent(dx, dx, dy, dz);
            out.ly = Vector.unitComponent(dy, dx, dy, dz);
            out.lz = Vector.unitComponent(dz, dx, dy, dz);
        }
        if (d > range) {
            out.r = out.g = out.b = 0;
            return;
        }
        double f = 1 / attenuation(d);
        out.r = intensity.getR() * f;
        out.g = intensity.getG() * f;
        out.b = intensity.getB() * f;
    }

    /** {@code kC + kL d + kQ d^2}, which must be positive. */
    private double attenuation(double d) {
        double attenuation = kC + kL * d + kQ * d * d;
        if (!(attenuation > 0)) {
            throw new IllegalStateException("light attenuation kC + kL d + kQ d^2 must be positive, but was "
                    + attenuation + " at distance " + d + " (kC=" + kC + ", kL=" + kL + ", kQ=" + kQ + ")");
        }
        return attenuation;
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

    /**
     * The unattenuated intensity.
     *
     * @return the intensity at the light's position, before attenuation
     */
    public Color getBaseIntensity() {
        return intensity;
    }

    /**
     * The constant attenuation factor.
     *
     * @return kC, at least 0
     */
    public double getKc() {
        return kC;
    }

    /**
     * The linear attenuation factor.
     *
     * @return kL, at least 0
     */
    public double getKl() {
        return kL;
    }

    /**
     * The quadratic attenuation factor.
     *
     * @return kQ, at least 0
     */
    public double getKq() {
        return kQ;
    }
}
