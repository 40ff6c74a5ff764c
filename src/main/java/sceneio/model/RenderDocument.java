package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import renderer.sampling.SamplingPattern;

/**
 * How to render: the image size and the render settings. Only width and height are required.
 *
 * @param width image width in pixels (required)
 * @param height image height in pixels (required)
 * @param antiAliasing camera rays per pixel (default one central ray)
 * @param threads render threads (default: the available processors)
 * @param bvh search with the BVH (default true) or by brute force
 * @param maxLevel deepest recursion of reflection and refraction (default 10)
 * @param shadowPattern placement of shadow rays on a light's disk (default jittered)
 * @param adaptiveShadows probe a few shadow rays first (default false)
 * @param glossySamples rays per glossy reflection or frosted refraction (default 16)
 * @param lightCutoff display steps of direct light a camera sample may leave out by not sampling lights too faint
 *     to matter, 0 (exact) to 255 (default 0.5: at most one step in the 8-bit image)
 * @param targetError sample progressively until the image's estimated RMSE is at most this many display steps
 *     (0..255 scale); the anti-aliasing's samples become the most a pixel receives (default: fixed sampling)
 * @param timeBudget sample progressively for this many seconds of wall time in all (default: fixed sampling)
 */
@JsonPropertyOrder({
    "width",
    "height",
    "antiAliasing",
    "threads",
    "bvh",
    "maxLevel",
    "shadowPattern",
    "adaptiveShadows",
    "glossySamples",
    "lightCutoff",
    "targetError",
    "timeBudget"
})
public record RenderDocument(
        Integer width,
        Integer height,
        SamplingDocument antiAliasing,
        Integer threads,
        Boolean bvh,
        Integer maxLevel,
        SamplingPattern shadowPattern,
        Boolean adaptiveShadows,
        Integer glossySamples,
        Double lightCutoff,
        Double targetError,
        Double timeBudget) {

    /**
     * This document with another image size.
     *
     * @param width the image width in pixels, or null when absent
     * @param height the image height in pixels, or null when absent
     * @return a copy of this document with only width and height replaced
     */
    public RenderDocument withSize(Integer width, Integer height) {
        return new RenderDocument(
                width,
                height,
                antiAliasing,
                threads,
                bvh,
                maxLevel,
                shadowPattern,
                adaptiveShadows,
                glossySamples,
                lightCutoff,
                targetError,
                timeBudget);
    }

    /**
     * This document with other anti-aliasing settings.
     *
     * @param antiAliasing the camera-ray sampling per pixel, or null for the default
     * @return a copy of this document with only the anti-aliasing replaced
     */
    public RenderDocument withAntiAliasing(SamplingDocument antiAliasing) {
        return new RenderDocument(
                width,
                height,
                antiAliasing,
                threads,
                bvh,
                maxLevel,
                shadowPattern,
                adaptiveShadows,
                glossySamples,
                lightCutoff,
                targetError,
                timeBudget);
    }

    /**
     * This document with another render thread count.
     *
     * @param threads the number of render threads, or null for the available processors
     * @return a copy of this document with only the thread count replaced
     */
    public RenderDocument withThreads(Integer threads) {
        return new RenderDocument(
                width,
                height,
                antiAliasing,
                threads,
                bvh,
                maxLevel,
                shadowPattern,
                adaptiveShadows,
                glossySamples,
                lightCutoff,
                targetError,
                timeBudget);
    }

    /**
     * This document with the search method chosen.
     *
     * @param bvh true to search with the BVH, false for brute force, null for the default (BVH)
     * @return a copy of this document with only the BVH choice replaced
     */
    public RenderDocument withBvh(Boolean bvh) {
        return new RenderDocument(
                width,
                height,
                antiAliasing,
                threads,
                bvh,
                maxLevel,
                shadowPattern,
                adaptiveShadows,
                glossySamples,
                lightCutoff,
                targetError,
                timeBudget);
    }

    /**
     * This document with another light cutoff.
     *
     * @param lightCutoff display steps of direct light a camera sample may leave out, 0 to 255, or null for the default
     * @return a copy of this document with only the light cutoff replaced
     */
    public RenderDocument withLightCutoff(Double lightCutoff) {
        return new RenderDocument(
                width,
                height,
                antiAliasing,
                threads,
                bvh,
                maxLevel,
                shadowPattern,
                adaptiveShadows,
                glossySamples,
                lightCutoff,
                targetError,
                timeBudget);
    }

    /**
     * This document with other progressive sampling (used by command-line overrides).
     *
     * @param targetError the target RMSE, or null when absent
     * @param timeBudget the time budget in seconds, or null when absent
     * @return a copy of this document with only the target error and time budget replaced
     */
    public RenderDocument withProgressive(Double targetError, Double timeBudget) {
        return new RenderDocument(
                width,
                height,
                antiAliasing,
                threads,
                bvh,
                maxLevel,
                shadowPattern,
                adaptiveShadows,
                glossySamples,
                lightCutoff,
                targetError,
                timeBudget);
    }
}
