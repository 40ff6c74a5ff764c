package renderer;

import java.util.Arrays;

/**
 * The 3 x 3 neighbourhood filters of the progressive planning, over per-pixel values of an image in row order: the
 * largest and the mean of each pixel's neighbourhood (clipped at the image's edges). Neighbours see much the same
 * noise, and an edge that one pixel's samples all missed is often seen by a neighbour's.
 *
 * <p>The values are sample variances: zero or positive (or NaN, which both filters pass on). Where most of an image
 * has converged (a soft shadow's lit ground and umbra), most neighbourhoods hold only zeros: the largest is raised
 * only around the values that are not 0, and the mean skips the neighbourhoods whose largest is 0.
 */
final class Neighbourhoods {
    private final int nX, nY;

    Neighbourhoods(int nX, int nY) {
        this.nX = nX;
        this.nY = nY;
    }

    /**
     * Per pixel, the largest of {@code values} over its neighbourhood and 0, into {@code out}: each value that is not
     * 0 raises the nine pixels around it (the maximum does not depend on the order it is taken in). A converging
     * image is mostly zeros, so this touches a few pixels of it, where filtering rows and columns touched all of them
     * twice: a command line's first plan ran that interpreted, 11-18 ms of a 0.25-0.35 s render of the POV-Ray scene.
     */
    double[] largest(double[] values, double[] out) {
        Arrays.fill(out, 0, nX * nY, 0);
        for (int y = 0; y < nY; y++) {
            int j0 = Math.max(0, y - 1), j1 = Math.min(nY - 1, y + 1);
            for (int x = 0, row = y * nX; x < nX; x++) {
                double v = values[row + x];
                if (v == 0) continue; // raises nothing above 0; a NaN is not 0 and is passed on
                int i0 = Math.max(0, x - 1), i1 = Math.min(nX - 1, x + 1);
                for (int j = j0; j <= j1; j++) {
                    for (int q = j * nX + i0, end = j * nX + i1; q <= end; q++) out[q] = Math.max(out[q], v);
                }
            }
        }
        return out;
    }

    /**
     * Per pixel, the mean of {@code values} over its neighbourhood, into {@code out}; {@code largest} holds the
     * neighbourhoods' largest values ({@link #largest}), and where that is 0 every value is, and so is the mean.
     * Elsewhere the neighbourhood is summed row by row, left to right.
     */
    double[] mean(double[] values, double[] largest, double[] out) {
        return mean(values, largest, out, true);
    }

    /**
     * As {@link #mean}, without the pixel itself: the mean of its 8 neighbours (fewer at the image's edges; 0 for an
     * image of one pixel).
     */
    double[] meanOfOthers(double[] values, double[] largest, double[] out) {
        return mean(values, largest, out, false);
    }

    private double[] mean(double[] values, double[] largest, double[] out, boolean withSelf) {
        for (int y = 0; y < nY; y++) {
            int j0 = Math.max(0, y - 1), j1 = Math.min(nY - 1, y + 1);
            for (int x = 0; x < nX; x++) {
                int p = y * nX + x, i0 = Math.max(0, x - 1), i1 = Math.min(nX - 1, x + 1);
                int count = (j1 - j0 + 1) * (i1 - i0 + 1) - (withSelf ? 0 : 1);
                if (largest[p] == 0 || count == 0) {
                    out[p] = 0;
                    continue;
                }
                double sum = 0;
                for (int j = j0; j <= j1; j++) {
                    for (int i = i0; i <= i1; i++) if (withSelf || j * nX + i != p) sum += values[j * nX + i];
                }
                out[p] = sum / count;
            }
        }
        return out;
    }
}
