package app;

import geometries.Geometry;
import primitives.Point;

/**
 * A glowing surface of the {@link StreetScene} (a lit window, a lamp globe) and a point on it that is clear of any
 * glazing bar, so a test can project the point into the image and check the pixel there is bright.
 *
 * @param surface the emissive geometry
 * @param point a point on or inside the surface where nothing of the same house covers it
 */
public record Landmark(Geometry surface, Point point) {}
