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
    /** The scene's name, never null. */
    public final String name;
    /** The colour of a ray that hits nothing; black unless set. */
    public Color background = Color.BLACK;
    /** The ambient light added to every hit; {@link AmbientLight#NONE} unless set. */
    public AmbientLight ambientLight = AmbientLight.NONE;
    /** The geometries of the scene; empty unless set. */
    public Geometries geometries = new Geometries();
    /** The light sources of the scene; empty unless set. */
    public List<LightSource> lights = new ArrayList<>();

    private long seed = 0x5EED_0F_5CE4EL;

    /**
     * Creates an empty scene with a black background, no ambient light, no geometry and no light.
     *
     * @param name the scene's name; not null
     */
    public Scene(String name) {
        this.name = Util.requireNonNull(name, "scene name");
    }

    /**
     * Sets the background colour and returns this scene.
     *
     * @param background the colour of rays that hit nothing; not null
     * @return this scene
     */
    public Scene setBackground(Color background) {
        this.background = Util.requireNonNull(background, "background");
        return this;
    }

    /**
     * Sets the ambient light and returns this scene.
     *
     * @param ambientLight the ambient light added to every hit; not null
     * @return this scene
     */
    public Scene setAmbientLight(AmbientLight ambientLight) {
        this.ambientLight = Util.requireNonNull(ambientLight, "ambient light");
        return this;
    }

    /**
     * Replaces the geometries and returns this scene.
     *
     * @param geometries the geometries to render; not null
     * @return this scene
     */
    public Scene setGeometries(Geometries geometries) {
        this.geometries = Util.requireNonNull(geometries, "geometries");
        return this;
    }

    /**
     * Replaces the light sources with a copy of the given list and returns this scene.
     *
     * @param lights the new light sources; neither the list nor any element may be null
     * @return this scene
     */
    public Scene setLights(List<LightSource> lights) {
        Util.requireNonNull(lights, "lights");
        for (int i = 0; i < lights.size(); i++) Util.requireNonNull(lights.get(i), "light " + i);
        this.lights = new ArrayList<>(lights);
        return this;
    }

    /**
     * Adds lights and returns this scene.
     *
     * @param lights the light sources appended to this scene's lights; neither the array nor any element may be null
     * @return this scene
     */
    public Scene addLights(LightSource... lights) {
        Util.requireNonNull(lights, "lights");
        for (int i = 0; i < lights.length; i++) Util.requireNonNull(lights[i], "light " + i);
        this.lights.addAll(java.util.Arrays.asList(lights));
        return this;
    }

    /**
     * The seed of all random sampling in renders of this scene.
     *
     * @return the seed from which every random sample of a render of this scene is derived
     */
    public long getSeed() {
        return seed;
    }

    /**
     * Sets the seed of all random sampling in renders of this scene and returns this scene.
     *
     * @param seed the seed from which every random sample is derived
     * @return this scene
     */
    public Scene setSeed(long seed) {
        this.seed = seed;
        return this;
    }

    /**
     * The scene's name.
     *
     * @return the scene's name, never null
     */
    public String getName() {
        return name;
    }
}
