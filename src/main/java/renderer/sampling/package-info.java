/**
 * Deterministic sample patterns (grid, jittered, Halton...) and the sampling configurations of anti-aliasing, soft
 * shadows, depth of field and glossy beams. Core: JDK only.
 */
package renderer.sampling;
