package distributed;

import java.io.Serializable;

/**
 * One rectangle of the image, rendered by one Spark task: columns {@code x0 .. x0 + width - 1} and rows
 * {@code y0 .. y0 + height - 1}. {@code index} numbers the tiles row by row from 0.
 */
public record Tile(int index, int x0, int y0, int width, int height) implements Serializable {}
