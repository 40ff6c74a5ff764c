package primitives;

/**
 * The library's fixed limits on what a scene may ask for, shared by every setting they bound so that each
 * message names the same number.
 */
public final class Limits {
    private Limits() {}

    /**
     * Most samples of one beam: camera rays per pixel, shadow rays per light and shading point, rays of a glossy
     * or frosted beam, lens samples (2^20; a million rays for one pixel is already hours of work).
     */
    public static final int MAX_SAMPLES = 1 << 20;
}
