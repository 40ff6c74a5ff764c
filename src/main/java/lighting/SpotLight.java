package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Util;
import primitives.Vector;

/**
 * A point light that shines along a direction: intensity scaled by {@code max(0, dir . l)^narrowBeam}, so the
 * exponent (default 1) narrows the beam. Attenuation, radius and samples work as for {@link PointLight}.
 */
public class SpotLight extends PointLight {
    private final Vector direction;
    private double narrowBeam = 1;

    /**
     * A spot light at {@code position} shining along {@code direction}, with beam exponent 1 and no attenuation.
     *
     * @param intensity the light's colour and strength on the beam's axis; not null
     * @param position where the light is; not null
     * @param direction the beam's axis; any length, normalized here; not null
     */
    public SpotLight(Color intensity, Point position, Vector direction) {
        super(intensity, position);
        this.direction = Util.requireNonNull(direction, "spot direction").normalize();
    }

    /**
     * The beam exponent: 1 is the plain cosine falloff, larger values narrow the beam.
     *
     * @param narrowBeam the exponent of the cosine falloff, at least 1 and finite
     * @return this light
     * @throws IllegalArgumentException if {@code narrowBeam} is below 1 or not finite
     */
    public SpotLight setNarrowBeam(double narrowBeam) {
        if (!(narrowBeam >= 1) || !Double.isFinite(narrowBeam)) {
            throw new IllegalArgumentException("narrowBeam must be >= 1 and finite, but was " + narrowBeam);
        }
        this.narrowBeam = narrowBeam;
        return this;
    }

    @Override
    public SpotLight setKc(double kC) {
        super.setKc(kC);
        return this;
    }

    @Override
    public SpotLight setKl(double kL) {
        super.setKl(kL);
        return this;
    }

    @Override
    public SpotLight setKq(double kQ) {
        super.setKq(kQ);
        return this;
    }

    @Override
    public SpotLight setRadius(double radius) {
        super.setRadius(radius);
        return this;
    }

    @Override
    public SpotLight setNumSamples(int numSamples) {
        super.setNumSamples(numSamples);
        return this;
    }

    @Override
    public SpotLight setRange(double range) {
        super.setRange(range);
        return this;
    }

    @Override
    public Color getIntensity(Point point) {
        if (point.equals(getPosition())) return Color.BLACK;
        double cos = direction.dotProduct(getL(point));
        if (!(cos > 0)) return Color.BLACK;
        double factor = narrowBeam == 1 ? cos : Math.pow(cos, narrowBeam);
        return super.getIntensity(point).scale(factor);
    }

    @Override
    public void illuminate(double x, double y, double z, LightSample out) {
        super.illuminate(x, y, z, out);
        if (out.distance == 0) return;
        double cos = direction.x * out.lx + direction.y * out.ly + direction.z * out.lz;
        if (!(cos > 0)) {
            out.r = out.g = out.b = 0;
            return;
        }
        double factor = narrowBeam == 1 ? cos : Math.pow(cos, narrowBeam);
        out.r *= factor;
        out.g *= factor;
        out.b *= factor;
    }

    /**
     * The beam's axis.
     *
     * @return the unit direction the light shines along
     */
    public Vector getDirection() {
        return direction;
    }

    /**
     * The beam exponent.
     *
     * @return the exponent of the cosine falloff, at least 1
     */
    public double getNarrowBeam() {
        return narrowBeam;
    }
}
