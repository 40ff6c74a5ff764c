package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Consumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Unit tests for {@link Material}: defaults, fluent setters and validation. */
class MaterialTest {

    @Test
    void defaults() {
        Material m = new Material();
        assertEquals(Double3.ONE, m.getKa());
        assertEquals(Double3.ZERO, m.getKd());
        assertEquals(Double3.ZERO, m.getKs());
        assertEquals(Double3.ZERO, m.getKr());
        assertEquals(Double3.ZERO, m.getKt());
        assertEquals(0, m.getShininess());
        assertEquals(1.0, m.getIndexOfRefraction());
        assertEquals(0.0, m.getRoughness());
        assertFalse(m.isReflective());
        assertFalse(m.isTransparent());
    }

    @Test
    void fluentSettersReturnTheSameMaterial() {
        Material m = new Material();
        assertSame(m, m.setKa(0.5));
        assertSame(m, m.setKd(0.2));
        assertSame(m, m.setKs(new Double3(0.1, 0.2, 0.3)));
        assertSame(m, m.setKr(0.4));
        assertSame(m, m.setKt(0.6));
        assertSame(m, m.setShininess(30));
        assertSame(m, m.setIndexOfRefraction(1.5));
        assertSame(m, m.setRoughness(0.25));
        assertEquals(new Double3(0.5), m.getKa());
        assertEquals(new Double3(0.2), m.getKd());
        assertEquals(new Double3(0.1, 0.2, 0.3), m.getKs());
        assertEquals(new Double3(0.4), m.getKr());
        assertEquals(new Double3(0.6), m.getKt());
        assertEquals(30, m.getShininess());
        assertEquals(1.5, m.getIndexOfRefraction());
        assertEquals(0.25, m.getRoughness());
        assertTrue(m.isReflective());
        assertTrue(m.isTransparent());
        // one non-zero channel is enough
        assertTrue(new Material().setKr(new Double3(0, 0, 0.1)).isReflective());
    }

    @Test
    void boundaryValuesAreAccepted() {
        Material m = new Material()
                .setKd(0)
                .setKs(1)
                .setShininess(0)
                .setIndexOfRefraction(1e-3)
                .setRoughness(0)
                .setRoughness(1);
        assertEquals(1e-3, m.getIndexOfRefraction());
        assertEquals(1e3, m.setIndexOfRefraction(1e3).getIndexOfRefraction());
        assertEquals(1.0, m.getRoughness());
        // HDR coefficients above 1 are allowed (not a probability)
        assertEquals(new Double3(2), m.setKd(2).getKd());
    }

    static Stream<Arguments> badValues() {
        return Stream.of(
                Arguments.of("kA", (Consumer<Material>) m -> m.setKa(-0.1), "-0.1"),
                Arguments.of("kD", (Consumer<Material>) m -> m.setKd(-1), "-1.0"),
                Arguments.of("kD", (Consumer<Material>) m -> m.setKd(Double.NaN), "NaN"),
                Arguments.of("kS", (Consumer<Material>) m -> m.setKs(new Double3(0, -0.5, 0)), "-0.5"),
                Arguments.of("kR", (Consumer<Material>) m -> m.setKr(Double.POSITIVE_INFINITY), "Infinity"),
                Arguments.of("kT", (Consumer<Material>) m -> m.setKt(-2), "-2.0"),
                Arguments.of("kT", (Consumer<Material>) m -> m.setKt(null), "null"),
                Arguments.of("shininess", (Consumer<Material>) m -> m.setShininess(-1), "-1"),
                Arguments.of("indexOfRefraction", (Consumer<Material>) m -> m.setIndexOfRefraction(0), "0.0"),
                Arguments.of("indexOfRefraction", (Consumer<Material>) m -> m.setIndexOfRefraction(Double.NaN), "NaN"),
                Arguments.of("indexOfRefraction", (Consumer<Material>) m -> m.setIndexOfRefraction(1001), "1001"),
                Arguments.of("roughness", (Consumer<Material>) m -> m.setRoughness(-0.01), "-0.01"),
                Arguments.of("roughness", (Consumer<Material>) m -> m.setRoughness(1.5), "1.5"));
    }

    @ParameterizedTest(name = "{0} = {2}")
    @MethodSource("badValues")
    void badValuesAreRejectedNamingParameterAndValue(String name, Consumer<Material> setter, String value) {
        Material m = new Material();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> setter.accept(m));
        assertTrue(e.getMessage().contains(name), e.getMessage());
        assertTrue(e.getMessage().contains(value), e.getMessage());
        // a rejected value leaves the material unchanged
        assertEquals(new Material().toString(), m.toString());
    }
}
