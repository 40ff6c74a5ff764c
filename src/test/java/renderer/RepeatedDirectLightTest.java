package renderer;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import sceneio.SceneLoader;

/**
 * With hard lights only, the progressive samples that shade a pixel's first hit again take its direct light from the
 * first of them (SimpleRayTracer): the image must be the one of samples that each compute it, and only the shadow rays
 * of the repeats are saved. Here the reference computes it for every sample because the scene also holds a soft light
 * that is black, which adds nothing to any colour but makes the direct light a matter of each sample's own beam.
 */
class RepeatedDirectLightTest {
    private static final String SCENE = """
            {
              "version": 1,
              "background": [10, 20, 40],
              "ambient": { "color": [30, 30, 30] },
              "camera": { "location": [0, -6, 2.5], "lookAt": [0, 0, 0.5], "up": [0, 0, 1],
                          "vpDistance": 1, "vpWidth": 1, "vpHeight": 0.75 },
              "render": { "width": 40, "height": 30, "threads": 2, "targetError": 0.3 },
              "lights": [
                { "type": "point", "color": [255, 240, 220], "position": [2, -1, 4] }EXTRA
              ],
              "geometries": [
                { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1],
                  "material": { "kD": 0.45, "kS": 0.2, "shininess": 60, "kR": 0.6, "roughness": 0.3 } },
                { "type": "sphere", "center": [0, 0, 1], "radius": 0.8,
                  "material": { "kD": [0.9, 0.5, 0.2], "kS": 0.3, "shininess": 40 }, "emission": [120, 60, 20] }
              ]
            }
            """;

    private static Camera render(String extraLight) throws Exception {
        Camera camera = SceneLoader.load(SCENE.replace("EXTRA", extraLight), "scene.json", Path.of("."))
                .camera();
        camera.renderImage();
        return camera;
    }

    @Test
    void repeatedSamplesReuseTheFirstHitsDirectLightAndChangeNoPixel() throws Exception {
        Camera hardOnly = render("");
        Camera withBlackSoftLight =
                render(",\n    { \"type\": \"point\", \"color\": [0, 0, 0], \"position\": [-3, 1, 5], \"radius\": 0.5,"
                        + " \"samples\": 4 }");
        assertNull(FeatureScenes.firstDifference(hardOnly.getImage(), withBlackSoftLight.getImage()));
        long reused = hardOnly.getLastStatistics().rays().shadow;
        long computed = withBlackSoftLight.getLastStatistics().rays().shadow;
        assertTrue(
                hardOnly.getLastProgressiveReport().samples() > 2L * 40 * 30,
                hardOnly.getLastProgressiveReport().describe());
        assertTrue(
                reused < computed, "shadow rays " + reused + " with the direct light reused, " + computed + " without");
    }
}
