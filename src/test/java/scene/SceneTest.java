package scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import geometries.Geometries;
import geometries.Sphere;
import java.util.ArrayList;
import java.util.List;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import org.junit.jupiter.api.Test;
import primitives.Color;
import primitives.Point;
import primitives.Vector;

/** Unit tests for {@link Scene}: defaults, fluent setters, validation. */
class SceneTest {
    @Test
    void defaultsAndFluentSetters() {
        Scene scene = new Scene("test");
        assertEquals("test", scene.getName());
        assertEquals(Color.BLACK, scene.background);
        assertSame(AmbientLight.NONE, scene.ambientLight);
        assertTrue(scene.geometries.isEmpty());
        assertTrue(scene.lights.isEmpty());
        Geometries g = new Geometries(new Sphere(Point.ZERO, 1));
        AmbientLight ambient = new AmbientLight(new Color(10, 10, 10));
        DirectionalLight sun = new DirectionalLight(new Color(1, 1, 1), Vector.AXIS_Z);
        assertSame(
                scene,
                scene.setBackground(new Color(1, 2, 3))
                        .setAmbientLight(ambient)
                        .setGeometries(g)
                        .addLights(sun)
                        .setSeed(42));
        assertEquals(new Color(1, 2, 3), scene.background);
        assertSame(ambient, scene.ambientLight);
        assertSame(g, scene.geometries);
        assertEquals(List.of(sun), scene.lights);
        assertEquals(42, scene.getSeed());
    }

    @Test
    void setLightsCopiesTheList() {
        List<LightSource> lights = new ArrayList<>();
        lights.add(new DirectionalLight(new Color(1, 1, 1), Vector.AXIS_Z));
        Scene scene = new Scene("copy").setLights(lights);
        lights.clear();
        assertEquals(1, scene.lights.size());
    }

    @Test
    void badInputIsRejected() {
        Scene scene = new Scene("bad");
        assertMessage(() -> new Scene(null), "scene name");
        assertMessage(() -> scene.setBackground(null), "background");
        assertMessage(() -> scene.setAmbientLight(null), "ambient light");
        assertMessage(() -> scene.setGeometries(null), "geometries");
        assertMessage(() -> scene.setLights(null), "lights");
        List<LightSource> withNull = new ArrayList<>();
        withNull.add(null);
        assertMessage(() -> scene.setLights(withNull), "light 0");
        assertMessage(() -> scene.addLights(new DirectionalLight(new Color(1, 1, 1), Vector.AXIS_Z), null), "light 1");
        assertMessage(() -> scene.addLights((LightSource[]) null), "lights");
        // rejected calls changed nothing
        assertTrue(scene.lights.isEmpty(), "a rejected addLights adds none of its lights");
        assertEquals(Color.BLACK, scene.background);
    }

    private static void assertMessage(Runnable action, String fragment) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, action::run);
        assertTrue(e.getMessage().contains(fragment), e.getMessage());
    }
}
