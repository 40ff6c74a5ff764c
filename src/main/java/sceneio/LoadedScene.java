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
 * @param files the files the scene read besides itself (OBJ, MTL, images), each once, as references relative to
 *     the scene file's folder, in the order they were read (what must travel with the scene file)
 */
public record LoadedScene(
        SceneDocument document, Scene scene, Camera camera, List<String> warnings, List<String> files) {
    /**
     * Copies the lists into unmodifiable ones.
     *
     * @param document the file as read
     * @param scene the scene
     * @param camera a camera on the scene with the file's render settings
     * @param warnings what was accepted but ignored, one line each; not null, no null element
     * @param files the files read besides the scene file, relative to its folder; not null, no null element
     */
    public LoadedScene {
        warnings = List.copyOf(warnings);
        files = List.copyOf(files);
    }

    /**
     * A loaded scene that read no other files.
     *
     * @param document the file as read
     * @param scene the scene
     * @param camera a camera on the scene with the file's render settings
     * @param warnings what was accepted but ignored, one line each; not null, no null element
     */
    public LoadedScene(SceneDocument document, Scene scene, Camera camera, List<String> warnings) {
        this(document, scene, camera, warnings, List.of());
    }
}
