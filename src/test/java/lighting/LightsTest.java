package lighting;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Double3;
import primitives.Point;
import primitives.Vector;

/** Unit tests for the light sources: intensity with attenuation and beam, direction, distance, validation. */
class LightsTest {
    private static final double DELTA = 1e-12;

    private static void assertColor(Color expected, Color actual) {
        assertEquals(expected.getR(), actual.getR(), DELTA, "red of " + actual);
        assertEquals(expected.getG(), actual.getG(), DELTA, "green of " + actual);
        assertEquals(expected.getB(), actual.getB(), DELTA, "blue of " + actual);
    }

    private static void assertMessage(Runnable action, String... fragments) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, action::run);
        for (String f : fragments) assertTrue(e.getMessage().contains(f), "'" + f + "' in: " + e.getMessage());
    }

    @Test
    void ambientLight() {
        assertColor(new Color(50, 25, 10), new AmbientLight(new Color(100, 50, 20), 0.5).getIntensity());
        assertColor(
                new Color(10, 25, 20),
                new AmbientLight(new Color(100, 50, 20), new Double3(0.1, 0.5, 1)).getIntensity());
        assertColor(new Color(100, 50, 20), new AmbientLight(new Color(100, 50, 20)).getIntensity());
        assertTrue(AmbientLight.NONE.getIntensity().isBlack());
        assertMessage(() -> new AmbientLight(new Color(1, 1, 1), -0.5), "ambient kA", "-0.5");
        assertMessage(() -> new AmbientLight(null, 0.5), "ambient intensity");
    }

    @Test
    void directionalLight() {
        DirectionalLight light = new DirectionalLight(new Color(10, 20, 30), new Vector(0, 0, -5));
        Point anywhere = new Point(1e6, -3, 7);
        // no attenuation, the same direction everywhere, infinitely far
        assertColor(new Color(10, 20, 30), light.getIntensity(anywhere));
        assertEquals(new Vector(0, 0, -1), light.getL(anywhere));
        assertEquals(new Vector(0, 0, -1), light.getDirection());
        assertEquals(Double.POSITIVE_INFINITY, light.getDistance(anywhere));
        assertNull(light.getPosition());
        assertEquals(0, light.getRadius());
        assertTrue(!light.isSoft());
        assertMessage(() -> new DirectionalLight(null, Vector.AXIS_Z), "intensity");
        assertMessage(() -> new DirectionalLight(new Color(1, 1, 1), null), "direction");
    }

    @Test
    void pointLightAttenuation() {
        PointLight light = new PointLight(new Color(300, 150, 60), new Point(1, 2, 3))
                .setKc(1)
                .setKl(0.1)
                .setKq(0.01);
        Point p = new Point(1, 2, 13); // 10 away
        // 1 / (1 + 0.1 * 10 + 0.01 * 100) = 1/3
        assertColor(new Color(100, 50, 20), light.getIntensity(p));
        assertEquals(10, light.getDistance(p), DELTA);
        assertEquals(new Vector(0, 0, 1), light.getL(p));
        assertEquals(new Point(1, 2, 3), light.getPosition());
        // the default is no attenuation: kC = 1, kL = kQ = 0
        PointLight plain = new PointLight(new Color(300, 150, 60), Point.ZERO);
        assertColor(new Color(300, 150, 60), plain.getIntensity(new Point(100, 0, 0)));
        assertEquals(1, plain.getKc());
        assertEquals(0, plain.getKl());
        assertEquals(0, plain.getKq());
        assertSame(plain, plain.setRadius(2).setNumSamples(9));
        assertTrue(plain.isSoft());
        assertTrue(!new PointLight(new Color(1, 1, 1), Point.ZERO).setRadius(2).isSoft(), "one sample is hard");
        assertTrue(
                !new PointLight(new Color(1, 1, 1), Point.ZERO).setNumSamples(9).isSoft(), "no radius is hard");
    }

    @Test
    void pointLightValidation() {
        PointLight light = new PointLight(new Color(1, 1, 1), Point.ZERO);
        assertMessage(() -> light.setKc(-1), "kC", "-1.0");
        assertMessage(() -> light.setKl(Double.NaN), "kL", "NaN");
        assertMessage(() -> light.setKq(Double.POSITIVE_INFINITY), "kQ", "Infinity");
        assertMessage(() -> light.setRadius(-0.5), "radius", "-0.5");
        assertMessage(() -> light.setNumSamples(0), "numSamples", "0");
        assertMessage(() -> new PointLight(null, Point.ZERO), "intensity");
        assertMessage(() -> new PointLight(new Color(1, 1, 1), null), "position");
        // all attenuation coefficients zero: reported when used
        PointLight none = new PointLight(new Color(1, 1, 1), Point.ZERO).setKc(0);
        assertThrows(IllegalStateException.class, () -> none.getIntensity(new Point(1, 0, 0)));
    }

    @Test
    void spotLightBeam() {
        SpotLight spot = new SpotLight(new Color(200, 100, 50), new Point(0, 0, 10), new Vector(0, 0, -2));
        // straight below: full intensity
        assertColor(new Color(200, 100, 50), spot.getIntensity(new Point(0, 0, 0)));
        // at 60 degrees off the beam: cos = 0.5
        Point oblique = new Point(10 * Math.sqrt(3), 0, 0);
        assertColor(new Color(100, 50, 25), spot.getIntensity(oblique));
        // narrow beam: cos^4
        spot.setNarrowBeam(4);
        assertEquals(4, spot.getNarrowBeam());
        assertColor(new Color(200 / 16.0, 100 / 16.0, 50 / 16.0), spot.getIntensity(oblique));
        // at 90 degrees and behind: dark
        assertTrue(spot.getIntensity(new Point(5, 0, 10)).isBlack());
        assertTrue(spot.getIntensity(new Point(0, 0, 20)).isBlack());
        // the spot's position itself: dark, not NaN
        assertTrue(spot.getIntensity(new Point(0, 0, 10)).isBlack());
        // attenuation combines with the beam: 1 / (1 + 0.1 * 20) at 60 degrees (distance 20)
        SpotLight attenuated =
                new SpotLight(new Color(300, 300, 300), new Point(0, 0, 10), new Vector(0, 0, -1)).setKl(0.1);
        assertColor(new Color(50, 50, 50), attenuated.getIntensity(oblique));
        assertEquals(new Vector(0, 0, -1), attenuated.getDirection());
        assertMessage(() -> spot.setNarrowBeam(0.5), "narrowBeam", "0.5");
        assertMessage(() -> spot.setNarrowBeam(Double.NaN), "narrowBeam", "NaN");
        assertMessage(() -> new SpotLight(new Color(1, 1, 1), Point.ZERO, null), "direction");
    }

    /**
     * The renderer's allocation-free {@code illuminate} gives {@code getL}, {@code getDistance} and
     * {@code getIntensity} bit for bit: seeded points around the light, points straight along each axis from it
     * (where the unit vector is exactly the axis) and points far and very near.
     */
    @Test
    void illuminateAgreesWithTheVectorMethodsBitForBit() {
        PointLight light = new PointLight(new Color(300, 200, 100), new Point(1.5, -2, 3))
                .setKl(0.01)
                .setKq(0.001);
        Random random = new Random(20261126);
        LightSample sample = new LightSample();
        for (int i = 0; i < 600; i++) {
            double scale = Math.pow(10, random.nextInt(13) - 6);
            double dx = scale * (random.nextDouble() * 2 - 1);
            double dy = i % 3 == 0 ? 0 : scale * (random.nextDouble() * 2 - 1);
            double dz = i % 6 == 0 ? 0 : scale * (random.nextDouble() * 2 - 1);
            Point p = new Point(1.5 + dx, -2 + dy, 3 + dz);
            if (p.equals(new Point(1.5, -2, 3))) continue;
            light.illuminate(p.x, p.y, p.z, sample);
            Vector l = light.getL(p);
            String where = "point " + p;
            assertEquals(light.getDistance(p), sample.distance, 0, where);
            assertEquals(l.x, sample.lx, 0, where);
            assertEquals(l.y, sample.ly, 0, where);
            assertEquals(l.z, sample.lz, 0, where);
            Color intensity = light.getIntensity(p);
            assertEquals(intensity.getR(), sample.r, 0, where);
            assertEquals(intensity.getB(), sample.b, 0, where);
        }
    }
}
