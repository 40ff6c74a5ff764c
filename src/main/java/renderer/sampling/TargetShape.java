package renderer.sampling;

/** The area a beam of rays is aimed at. */
public enum TargetShape {
    /** A square of side 1 centred on the origin (scaled to a pixel, for example). */
    RECTANGLE,
    /** A disk of diameter 1 centred on the origin (scaled to a light or a lens aperture). */
    CIRCLE
}
