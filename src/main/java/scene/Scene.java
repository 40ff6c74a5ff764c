package scene;

import geometries.Geometries;
import java.util.ArrayList;
import java.util.List;
import lighting.AmbientLight;
import lighting.LightSource;
import primitives.Color;
import primitives.Util;

/**
 * What is rendered: a name, a background colour, the ambient light, the geometries and the lights, plus the seed
 * of every random sample (so a scene renders the same on any machine and any thread count). Built fluently.
 */
public class Scene {
    public final String name;
    public Color background = Color.BLACK;
    public AmbientLight ambientLight = AmbientLight.NONE;
    public Geometries geometries = new Geometries();
    public List<LightSource> lights = new ArrayList<>();
    private long seed = 0x5EED_0F_5CE4EL;

    public Scene(String name) {
        this.name = Util.requireNonNull(name, "scene name");
    }

    public Scene setBackground(Color background) {
        this.background = Util.requireNonNull(background, "background");
        return this;
    }

    public Scene setAmbientLight(AmbientLight ambientLight) {
        this.ambientLight = Util.requireNonNull(ambientLight, "ambient light");
        return this;
    }

    public Scene setGeometries(Geometries geometries) {
        this.geometries = Util.requireNonNull(geometries, "geometries");
        return this;
    }

    public Scene setLights(List<LightSource> lights) {
        Util.requireNonNull(lights, "lights");
        for (int i = 0; i < lights.size(); i++) Util.requireNonNull(lights.get(i), "light " + i);
        this.lights = new ArrayList<>(lights);
        return this;
    }

    /** Adds lights and returns this scene. */
    public Scene addLights(LightSource... lights) {
        Util.requireNonNull(lights, "lights");
        for (int i = 0; i < lights.length; i++) Util.requireNonNull(lights[i], "light " + i);
        this.lights.addAll(java.util.Arrays.asList(lights));
        return this;
    }

    /** The seed of all random sampling in renders of this scene. */
    public long getSeed() {
        return seed;
    }

    public Scene setSeed(long seed) {
        this.seed = seed;
        return this;
    }

    public String getName() {
        return name;
    }
}
