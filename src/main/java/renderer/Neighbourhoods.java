package renderer;

/**
 * The 3 x 3 neighbourhood filters of the progressive planning, over per-pixel values of an image in row order: the
 * largest and the mean of each pixel's neighbourhood (clipped at the image's edges). Neighbours see much the same
 * noise, and an edge that one pixel's samples all missed is often seen by a neighbour's.
 *
 * <p>The values are sample variances: zero or positive (or NaN, which both filters pass on). Where most of an image
 * has converged (a soft shadow's lit ground and umbra), most neighbourhoods hold only zeros, and the mean skips them
 * by the largest: the planning filters the whole image twice per pass.
 */
final class Neighbourhoods {
    private final int nX, nY;
    /** Per column of the current row, the largest value of the rows around it. */
    private final double[] columnLargest;

    Neighbourhoods(int nX, int nY) {
        this.nX = nX;
        this.nY = nY;
        columnLargest = new double[nX];
    }

    /**
     * Per pixel, the largest of {@code values} over its neighbourhood and 0, into {@code out}: the rows' largest per
     * column, then across three columns (the maximum does not depend on the order it is taken in).
     */
    double[] largest(double[] values, double[] out) {
        double[] column = columnLargest;
        for (int y = 0; y < nY; y++) {
            int above = Math.max(0, y - 1) * nX, below = Math.min(nY - 1, y + 1) * nX, row = y * nX;
            for (int x = 0; x < nX; x++) {
                column[x] = Math.max(Math.max(Math.max(0, values[above + x]), values[row + x]), values[below + x]);
            }
            for (int x = 0; x < nX; x++) {
                double left = column[Math.max(0, x - 1)], right = column[Math.min(nX - 1, x + 1)];
                out[row + x] = Math.max(Math.max(left, column[x]), right);
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
        for (int y = 0; y < nY; y++) {
            int j0 = Math.max(0, y - 1), j1 = Math.min(nY - 1, y + 1);
            for (int x = 0; x < nX; x++) {
                int p = y * nX + x;
                if (largest[p] == 0) {
                    out[p] = 0;
                    continue;
                }
                int i0 = Math.max(0, x - 1), i1 = Math.min(nX - 1, x + 1);
                double sum = 0;
                for (int j = j0; j <= j1; j++) {
                    for (int i = i0; i <= i1; i++) sum += values[j * nX + i];
                }
                out[p] = sum / ((j1 - j0 + 1) * (i1 - i0 + 1));
            }
        }
        return out;
    }
}
