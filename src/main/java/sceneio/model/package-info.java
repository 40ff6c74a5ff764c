/**
 * The scene file's documents as Java records, one per JSON object kind (docs/SCENE-FORMAT.md). Tool: needs Jackson.
 */
package sceneio.model;
