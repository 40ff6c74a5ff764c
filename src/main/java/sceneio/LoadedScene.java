package sceneio;

import java.util.List;
import renderer.Camera;
import scene.Scene;
import sceneio.model.SceneDocument;

/**
 * A scene file turned into core objects, ready to render: {@code camera.renderImage()}.
 *
 * @param document the file as read (write it back with {@link SceneWriter})
 * @param scene the scene
 * @param camera a camera on the scene with the file's render settings
 * @param warnings what was accepted but ignored (e.g. OBJ statements), one line each
 */
public record LoadedScene(SceneDocument document, Scene scene, Camera camera, List<String> warnings) {
    /**
     * Copies the warnings into an unmodifiable list.
     *
     * @param document the file as read
     * @param scene the scene
     * @param camera a camera on the scene with the file's render settings
     * @param warnings what was accepted but ignored, one line each; not null, no null element
     */
    public LoadedScene {
        warnings = List.copyOf(warnings);
    }
}
