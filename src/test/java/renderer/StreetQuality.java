package renderer;

import java.util.Locale;

/**
 * How hard {@link StreetSceneTest} works: a preview that keeps {@code mvn test} quick, or the full quality of the
 * README picture, chosen with {@code -Dstreet.quality=full} (default {@code preview}).
 *
 * @param name as given on the command line
 * @param width image width in pixels
 * @param height image height in pixels
 * @param aaSamples anti-aliasing samples per pixel (a square GRID)
 * @param shadowSamples shadow rays per lamp and shading point for soft shadows
 * @param bvhOffWidth width of the brute-force (BVH off) comparison, rendered with the BVH too at that size (the
 *     height keeps the aspect ratio): brute force tests every primitive per ray, about 100 times the BVH's cost
 *     here, so both qualities compare a smaller image
 * @param cheapSeconds renders faster than this are repeated and the median of three is reported
 */
record StreetQuality(
        String name, int width, int height, int aaSamples, int shadowSamples, int bvhOffWidth, double cheapSeconds) {
    static final StreetQuality PREVIEW = new StreetQuality("preview", 320, 200, 9, 9, 96, 2);
    static final StreetQuality FULL = new StreetQuality("full", 1600, 1000, 81, 81, 400, 30);

    /** The quality selected by the system property {@code street.quality} ({@code preview} or {@code full}). */
    static StreetQuality fromSystemProperty() {
        String value = System.getProperty("street.quality", PREVIEW.name).trim().toLowerCase(Locale.ROOT);
        return switch (value) {
            case "preview", "" -> PREVIEW;
            case "full" -> FULL;
            default ->
                throw new IllegalArgumentException(
                        "street.quality must be 'preview' or 'full', but was '" + value + "'");
        };
    }

    int bvhOffHeight() {
        return bvhOffWidth * height / width;
    }
}
