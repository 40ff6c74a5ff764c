package sceneio.model;

/** A geometry with an appearance: every geometry document but a group. */
public interface SurfaceDocument {
    /**
     * The material, or null for the default material.
     *
     * @return the material reference, or null for the default material
     */
    MaterialRef material();

    /**
     * The emission colour, or null for black.
     *
     * @return the emitted colour as RGB, or null for black
     */
    Vec3 emission();
}
