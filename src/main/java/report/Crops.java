package report;

import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;
import renderer.ImageWriter;

/** A grid of enlarged crops: one row per variant, one column per sample count, the reference last. */
final class Crops {
    private static final int SCALE = 3, GAP = 4, LABEL = 16;

    private Crops() {}

    /** A labelled image with {@code cells[row][column]} cropped by {@code crop} (fractions) and enlarged. */
    static BufferedImage grid(List<String> rows, List<String> columns, ImageWriter[][] cells, double[] crop) {
        ImageWriter any = cells[0][0];
        int x0 = (int) (crop[0] * any.getNx()), y0 = (int) (crop[1] * any.getNy());
        int w = Math.max(1, (int) (crop[2] * any.getNx())), h = Math.max(1, (int) (crop[3] * any.getNy()));
        int cellW = w * SCALE, cellH = h * SCALE, labelW = 110;
        BufferedImage out = new BufferedImage(
                labelW + columns.size() * (cellW + GAP),
                LABEL + rows.size() * (cellH + GAP),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(java.awt.Color.WHITE);
        g.fillRect(0, 0, out.getWidth(), out.getHeight());
        g.setColor(java.awt.Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        for (int c = 0; c < columns.size(); c++) g.drawString(columns.get(c), labelW + c * (cellW + GAP) + 2, 12);
        for (int r = 0; r < rows.size(); r++) {
            int top = LABEL + r * (cellH + GAP);
            g.drawString(rows.get(r), 4, top + cellH / 2);
            for (int c = 0; c < columns.size(); c++) {
                ImageWriter image = cells[r][c];
                if (image == null) continue;
                BufferedImage full = image.toBufferedImage();
                BufferedImage part =
                        full.getSubimage(x0, y0, Math.min(w, full.getWidth() - x0), Math.min(h, full.getHeight() - y0));
                g.drawImage(
                        part, labelW + c * (cellW + GAP), top, part.getWidth() * SCALE, part.getHeight() * SCALE, null);
            }
        }
        g.dispose();
        return out;
    }
}
