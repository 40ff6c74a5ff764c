package distributed;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * How an image is split into tiles: {@code columns x rows} rectangles whose edges are at
 * {@code floor(i * width / columns)}, so tiles differ in size by at most one pixel and cover every pixel once.
 */
public record TileGrid(int columns, int rows) {
    private static final Pattern GRID = Pattern.compile("(\\d{1,6})x(\\d{1,6})");
    private static final Pattern COUNT = Pattern.compile("\\d{1,9}");

    public TileGrid {
        if (columns < 1 || rows < 1) {
            throw new IllegalArgumentException(
                    "a tile grid needs at least 1 x 1 tiles, but was " + columns + "x" + rows);
        }
    }

    /**
     * Reads {@code COLSxROWS} (e.g. {@code 4x4}) or a tile count N, which is split into the most nearly square
     * grid with at least as many columns as rows ({@code 16} is 4x4, {@code 8} is 4x2, a prime p is px1).
     */
    public static TileGrid parse(String spec) {
        String s = spec.trim().toLowerCase(Locale.ROOT);
        Matcher grid = GRID.matcher(s);
        if (grid.matches()) return new TileGrid(Integer.parseInt(grid.group(1)), Integer.parseInt(grid.group(2)));
        if (COUNT.matcher(s).matches()) {
            int n = Integer.parseInt(s);
            if (n < 1) throw new IllegalArgumentException("--tiles must be at least 1, but was " + spec);
            int rows = (int) Math.sqrt(n);
            while (n % rows != 0) rows--;
            return new TileGrid(n / rows, rows);
        }
        throw new IllegalArgumentException(
                "--tiles must be COLSxROWS (e.g. 4x4) or a tile count, but was '" + spec + "'");
    }

    public int count() {
        return columns * rows;
    }

    /**
     * The tiles of a {@code width x height} image, row by row.
     *
     * @throws IllegalArgumentException if there are more columns than pixels across or rows than pixels down
     */
    public List<Tile> split(int width, int height) {
        if (columns > width || rows > height) {
            throw new IllegalArgumentException("cannot split a " + width + " x " + height + " image into " + columns
                    + "x" + rows + " tiles: at most one column per pixel across and one row per pixel down");
        }
        List<Tile> tiles = new ArrayList<>(count());
        for (int r = 0; r < rows; r++) {
            int y0 = (int) ((long) r * height / rows), y1 = (int) ((long) (r + 1) * height / rows);
            for (int c = 0; c < columns; c++) {
                int x0 = (int) ((long) c * width / columns), x1 = (int) ((long) (c + 1) * width / columns);
                tiles.add(new Tile(tiles.size(), x0, y0, x1 - x0, y1 - y0));
            }
        }
        return tiles;
    }

    @Override
    public String toString() {
        return columns + "x" + rows;
    }
}
