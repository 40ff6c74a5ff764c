package distributed;

import java.io.Serializable;

/**
 * A frame as its task returns it: the PNG file's bytes, encoded on the executor (a few bytes per pixel travel to
 * the driver instead of 24 for linear pixels, and the encoding work is spread over the cluster).
 */
public record RenderedFrame(int frame, byte[] png) implements Serializable {}
