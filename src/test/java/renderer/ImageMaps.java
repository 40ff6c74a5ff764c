package renderer;

import primitives.Color;

/**
 * Boolean per-pixel maps computed from rendered images, for assertions about where one render differs from
 * another: which pixels changed, which lie on an edge, and a map grown by a few pixels.
 */
final class ImageMaps {
    private ImageMaps() {}

    /** Largest absolute channel difference between two colours. */
    static double channelDifference(Color a, Color b) {
        return Math.max(
                Math.abs(a.getR() - b.getR()), Math.max(Math.abs(a.getG() - b.getG()), Math.abs(a.getB() - b.getB())));
    }

    /** Pixels whose colours differ by more than {@code tolerance} in some channel (0 = any difference at all). */
    static boolean[][] changed(ImageWriter a, ImageWriter b, double tolerance) {
        boolean[][] map = new boolean[a.getNy()][a.getNx()];
        for (int y = 0; y < a.getNy(); y++) {
            for (int x = 0; x < a.getNx(); x++) {
                Color p = a.getPixel(x, y), q = b.getPixel(x, y);
                map[y][x] = tolerance == 0 ? !p.equals(q) : channelDifference(p, q) > tolerance;
            }
        }
        return map;
    }

    /**
     * Edge pixels: those with a neighbour (of the 8 around) whose colour differs by more than {@code contrast} in
     * some channel, after clamping both to the displayable 0..255 (differences above white are invisible).
     */
    static boolean[][] edges(ImageWriter image, double contrast) {
        int nx = image.getNx(), ny = image.getNy();
        boolean[][] map = new boolean[ny][nx];
        for (int y = 0; y < ny; y++) {
            for (int x = 0; x < nx; x++) {
                Color c = clamp(image.getPixel(x, y));
                for (int dy = -1; dy <= 1 && !map[y][x]; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= nx || qy >= ny) continue;
                        if (channelDifference(c, clamp(image.getPixel(qx, qy))) > contrast) {
                            map[y][x] = true;
                            break;
                        }
                    }
                }
            }
        }
        return map;
    }

    /** The map grown by {@code radius} pixels (a square neighbourhood). */
    static boolean[][] dilate(boolean[][] map, int radius) {
        int ny = map.length, nx = map[0].length;
        boolean[][] out = new boolean[ny][nx];
        for (int y = 0; y < ny; y++) {
            for (int x = 0; x < nx; x++) {
                if (!map[y][x]) continue;
                for (int qy = Math.max(0, y - radius); qy <= Math.min(ny - 1, y + radius); qy++) {
                    for (int qx = Math.max(0, x - radius); qx <= Math.min(nx - 1, x + radius); qx++) {
                        out[qy][qx] = true;
                    }
                }
            }
        }
        return out;
    }

    static int count(boolean[][] map) {
        int n = 0;
        for (boolean[] row : map) for (boolean b : row) if (b) n++;
        return n;
    }

    /** Display value of a linear colour: each channel clamped to 0..255, as the PNG writer does. */
    static Color clamp(Color c) {
        return new Color(clamp(c.getR()), clamp(c.getG()), clamp(c.getB()));
    }

    private static double clamp(double v) {
        return Math.max(0, Math.min(255, v));
    }
}
