package app;

import java.nio.file.Path;
import renderer.Camera;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import sceneio.SceneExporter;

/**
 * Writes the street scene as a scene file, {@code scenes/street.json} with its meshes in {@code scenes/models/}:
 * the README's main job renders it, and users can change it without writing Java. The file holds the "good"
 * settings of docs/ACCURACY.md at half the README picture's size: 800 x 500, 16 HALTON camera rays per pixel, lamps
 * of radius 10 with adaptive soft shadows of at most 9 rays per lamp and camera ray (5 probes, 4 more in penumbrae).
 *
 * <p>Run after changing {@link StreetScene}: {@code mvn -q compile exec:java -Dexec.mainClass=app.StreetSceneFile}.
 * {@code StreetSceneFileTest} checks that the file still renders exactly what the Java scene renders.
 */
public final class StreetSceneFile {
    /** The file's image size in pixels, camera rays per pixel and shadow rays per lamp. */
    public static final int WIDTH = 800, HEIGHT = 500, CAMERA_RAYS = 16, SHADOW_RAYS = 9;
    /** The radius of the file's disk lamps, in scene units. */
    public static final double LAMP_RADIUS = 10;

    private StreetSceneFile() {}

    /**
     * The street scene and camera the file holds, at the given resolution.
     *
     * @param street the street to view
     * @param width image width in pixels
     * @param height image height in pixels
     * @return a camera builder with 16 Halton camera rays per pixel and adaptive jittered shadow sampling
     */
    public static Camera.Builder camera(StreetScene street, int width, int height) {
        return street.camera(width, height)
                .setSamplingConfig(new SamplingConfig(CAMERA_RAYS, TargetShape.RECTANGLE, SamplingPattern.HALTON))
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, true));
    }

    /**
     * The street with the file's lamps.
     *
     * @return a new street with disk lamps of radius {@link #LAMP_RADIUS} and {@link #SHADOW_RAYS} samples
     */
    public static StreetScene street() {
        return new StreetScene(StreetOptions.soft(LAMP_RADIUS, SHADOW_RAYS));
    }

    /**
     * Writes the street scene file and its meshes.
     *
     * @param args optionally the scene file to write (default {@code scenes/street.json})
     */
    public static void main(String[] args) {
        Path file = Path.of(args.length > 0 ? args[0] : "scenes/street.json");
        StreetScene street = street();
        SceneExporter.export(street.scene(), camera(street, WIDTH, HEIGHT).build(), file);
        System.out.println("wrote " + file + " (" + street.primitiveCount() + " primitives)");
    }
}
