package robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Hit points of shapes far from the origin lie within about an ulp of the distance of the exact surface. */
class PrecisionAtDistanceTest {
    @ParameterizedTest
    @ValueSource(doubles = {1e3, 1e6, 1e9, 1e12})
    void sphereHitPointsAreWithinTwoUlpsOfTheSurface(double distance) {
        PrecisionProbe.Result r = PrecisionProbe.sphere(distance, 300, 17);
        assertEquals(300, r.hits());
        assertEquals(0, r.nonFinite());
        assertTrue(r.maxUlps() <= 2, "max error " + r.maxUlps() + " ulps at " + distance);
    }

    @ParameterizedTest
    @ValueSource(doubles = {1e3, 1e6, 1e9, 1e12})
    void triangleHitPointsAreWithinTwoUlpsOfThePlane(double distance) {
        PrecisionProbe.Result r = PrecisionProbe.triangle(distance, 300, 17);
        assertTrue(r.hits() > 150);
        assertEquals(0, r.nonFinite());
        assertTrue(r.maxUlps() <= 2, "max error " + r.maxUlps() + " ulps at " + distance);
    }
}
