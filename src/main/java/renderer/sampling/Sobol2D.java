package renderer.sampling;

/**
 * The first two dimensions of the Sobol sequence: a (0, 2)-sequence in base 2, whose every prefix of 2^m points (and
 * every aligned block of them) puts one point in each elementary rectangle of area 2^-m of the unit square. A digital
 * shift, the exclusive or of a random 32-bit pattern per coordinate, keeps that structure, so two shifts give two
 * independent low-discrepancy copies. Point k of a coordinate is computed from k's bits (Kollig and Keller's loop for
 * the second).
 */
public final class Sobol2D {
    private Sobol2D() {}

    /**
     * The 32-bit digital shift of a uniform number in [0, 1).
     *
     * @param uniform a number in [0, 1)
     * @return its first 32 bits
     */
    public static int shift(double uniform) {
        return (int) (long) (uniform * 0x1p32);
    }

    /**
     * The first coordinate of point {@code index}, digitally shifted: the van der Corput radical inverse in base 2.
     *
     * @param index the point's index, from 0
     * @param shift the coordinate's digital shift
     * @return the coordinate, in [0, 1)
     */
    public static double x(int index, int shift) {
        return ((Integer.reverse(index) ^ shift) & 0xFFFFFFFFL) * 0x1p-32;
    }

    /**
     * The second coordinate of point {@code index}, digitally shifted.
     *
     * @param index the point's index, from 0
     * @param shift the coordinate's digital shift
     * @return the coordinate, in [0, 1)
     */
    public static double y(int index, int shift) {
        int bits = shift;
        for (int i = index, column = 1 << 31; i != 0; i >>>= 1, column ^= column >>> 1) {
            if ((i & 1) != 0) bits ^= column;
        }
        return (bits & 0xFFFFFFFFL) * 0x1p-32;
    }
}
