package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;
import java.util.Map;

/**
 * A scene file as written: what to render (background, ambient light, materials, lights, geometries, seed) and
 * how (camera, render settings). Fields absent from the file are null here; the loader checks what is required
 * and applies the defaults, so writing a document back gives the same file content.
 *
 * @param version the format version; absent or 1
 * @param name the scene's name (default: the file name)
 * @param seed seed of every random sample (default: the library's fixed seed)
 * @param background colour of rays that hit nothing (default black)
 * @param ambient the ambient light (default none)
 * @param camera where the camera is and where it looks (required)
 * @param render resolution and render settings (required: at least width and height)
 * @param materials named materials that geometries refer to by name
 * @param prototypes named geometries that {@code instance} geometries place without copying them
 * @param lights the light sources
 * @param geometries the geometries
 */
@JsonPropertyOrder({
    "version",
    "name",
    "seed",
    "background",
    "ambient",
    "camera",
    "render",
    "materials",
    "prototypes",
    "lights",
    "geometries"
})
public record SceneDocument(
        Integer version,
        String name,
        Long seed,
        Vec3 background,
        AmbientDocument ambient,
        CameraDocument camera,
        RenderDocument render,
        Map<String, MaterialDocument> materials,
        Map<String, GeometryDocument> prototypes,
        List<LightDocument> lights,
        List<GeometryDocument> geometries) {

    /**
     * This document with other render settings (used by command-line overrides).
     *
     * @param render the new render settings, or null when absent
     * @return a copy of this document with only the render settings replaced
     */
    public SceneDocument withRender(RenderDocument render) {
        return new SceneDocument(
                version, name, seed, background, ambient, camera, render, materials, prototypes, lights, geometries);
    }

    /**
     * This document with another camera (used by command-line overrides).
     *
     * @param camera the new camera, or null when absent
     * @return a copy of this document with only the camera replaced
     */
    public SceneDocument withCamera(CameraDocument camera) {
        return new SceneDocument(
                version, name, seed, background, ambient, camera, render, materials, prototypes, lights, geometries);
    }
}
