package renderer;

/** The ray tracers a {@link Camera.Builder} can create for a scene. */
public enum RayTracerType {
    /** {@link SimpleRayTracer}: Phong shading, shadows, reflection and refraction. */
    SIMPLE
}
