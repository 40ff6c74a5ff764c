/**
 * Scene files: JSON read with Jackson into the documents of {@link sceneio.model}, checked with one-line errors that
 * say where and what is allowed, built into scenes and cameras; and written back. Tool: needs Jackson.
 */
package sceneio;
