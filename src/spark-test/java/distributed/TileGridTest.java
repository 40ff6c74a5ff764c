package distributed;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Tile grids: parsing, and tiles that cover every pixel exactly once with sizes within one pixel. */
class TileGridTest {
    @Test
    void gridsAndCountsAreParsed() {
        assertEquals(new TileGrid(4, 4), TileGrid.parse("4x4"));
        assertEquals(new TileGrid(3, 2), TileGrid.parse(" 3X2 "));
        assertEquals(new TileGrid(2, 2), TileGrid.parse("4"));
        assertEquals(new TileGrid(4, 4), TileGrid.parse("16"));
        assertEquals(new TileGrid(4, 2), TileGrid.parse("8"));
        assertEquals(new TileGrid(7, 1), TileGrid.parse("7"));
        assertEquals(new TileGrid(1, 1), TileGrid.parse("1"));
        for (String bad : List.of("0", "0x3", "3x0", "-4", "4x", "x4", "4*4", "", "99999999999")) {
            assertThrows(IllegalArgumentException.class, () -> TileGrid.parse(bad), bad);
        }
    }

    @Test
    void tilesCoverEveryPixelOnce() {
        for (int w : new int[] {1, 7, 16, 61, 480}) {
            for (int h : new int[] {1, 5, 47, 320}) {
                for (TileGrid grid : List.of(
                        new TileGrid(1, 1),
                        new TileGrid(2, 2),
                        new TileGrid(4, 4),
                        new TileGrid(7, 3),
                        new TileGrid(w, 1),
                        new TileGrid(1, h))) {
                    if (grid.columns() > w || grid.rows() > h) continue;
                    int[] covered = new int[w * h];
                    List<Tile> tiles = grid.split(w, h);
                    assertEquals(grid.count(), tiles.size());
                    for (int i = 0; i < tiles.size(); i++) {
                        Tile t = tiles.get(i);
                        assertEquals(i, t.index());
                        assertTrue(t.width() >= w / grid.columns() && t.width() <= w / grid.columns() + 1, t + "");
                        assertTrue(t.height() >= h / grid.rows() && t.height() <= h / grid.rows() + 1, t + "");
                        for (int y = t.y0(); y < t.y0() + t.height(); y++) {
                            for (int x = t.x0(); x < t.x0() + t.width(); x++) covered[y * w + x]++;
                        }
                    }
                    for (int c : covered) assertEquals(1, c, grid + " of " + w + " x " + h);
                }
            }
        }
    }

    @Test
    void moreTilesThanPixelsAreRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new TileGrid(5, 1).split(4, 4));
        assertTrue(e.getMessage().startsWith("cannot split a 4 x 4 image into 5x1 tiles"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new TileGrid(1, 5).split(4, 4));
    }
}
