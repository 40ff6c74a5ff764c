/** The scene: geometry, lights, ambient light and background, as the renderer takes them. Core: JDK only. */
package scene;
