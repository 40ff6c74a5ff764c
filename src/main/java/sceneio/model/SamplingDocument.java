package sceneio.model;

import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;

/**
 * Anti-aliasing: camera rays per pixel, spread over a target shape by a pattern; optionally adaptive.
 *
 * @param samples rays per pixel, 1 (off) to 1048576 (required)
 * @param shape rectangle or circle (default rectangle)
 * @param pattern grid, jittered, random or halton (default jittered)
 * @param adaptiveThreshold colour difference (0..255 scale) that triggers refinement; absent = not adaptive
 */
public record SamplingDocument(Integer samples, TargetShape shape, SamplingPattern pattern, Double adaptiveThreshold) {}
