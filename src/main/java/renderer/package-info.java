/**
 * Rendering: the {@link renderer.Camera} (view, tiles, threads), the ray tracer (Phong shading, shadows,
 * reflection, refraction, soft shadows, glossy surfaces, light cut-off), effect planning, render settings and
 * statistics, and image output. Core: JDK only.
 */
package renderer;
