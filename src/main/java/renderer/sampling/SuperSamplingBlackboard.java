package renderer.sampling;

/**
 * Generates the 2D offsets of a beam of rays over a target area: the square {@code [-1/2, 1/2]^2} for
 * {@link TargetShape#RECTANGLE} or the disk of diameter 1 for {@link TargetShape#CIRCLE}; callers scale them to
 * the pixel, light or lens.
 *
 * <p>The requested count is honoured exactly. GRID and JITTERED use {@code round(sqrt(n))} rows whose lengths
 * differ by at most one, so 5 samples are a row of 3 and a row of 2, not a silent 2 x 2. Disks are covered by the
 * concentric mapping of Shirley and Chiu, which keeps the strata of the square intact.
 */
public final class SuperSamplingBlackboard {
    private SuperSamplingBlackboard() {}

    /**
     * The offsets for {@code config} as a new array of x, y pairs.
     *
     * @param config the sample count, target shape and pattern
     * @param random the random stream for JITTERED, RANDOM and HALTON; GRID ignores it
     * @return a new array of {@code 2 * config.getSampleCount()} offsets, x then y for each sample
     */
    public static double[] getSampleOffsets(SamplingConfig config, SampleStream random) {
        double[] out = new double[2 * config.getSampleCount()];
        getSampleOffsets(config.getSampleCount(), config.getShape(), config.getPattern(), random, out);
        return out;
    }

    /**
     * Writes {@code count} x, y pairs into {@code out}. {@code random} feeds JITTERED, RANDOM and the HALTON
     * rotation; GRID ignores it. A single sample is always the centre.
     *
     * @param count the number of samples, at least 1
     * @param shape the square {@code [-1/2, 1/2]^2} or the disk of diameter 1
     * @param pattern how the samples are placed
     * @param random the random stream; may be null for GRID
     * @param out the array receiving x, y pairs in its first {@code 2 * count} elements
     * @throws IllegalArgumentException if {@code count} is below 1 or {@code out} holds fewer than {@code count} pairs
     */
    public static void getSampleOffsets(
            int count, TargetShape shape, SamplingPattern pattern, SampleStream random, double[] out) {
        if (count < 1) throw new IllegalArgumentException("sample count must be >= 1, but was " + count);
        if (out.length < 2 * count) {
            throw new IllegalArgumentException(
                    "output holds " + out.length / 2 + " samples, but " + count + " requested");
        }
        if (count == 1) {
            out[0] = 0;
            out[1] = 0;
            return;
        }
        switch (pattern) {
            case GRID -> stratified(count, null, out);
            case JITTERED -> stratified(count, random, out);
            case RANDOM -> {
                for (int i = 0; i < count; i++) {
                    out[2 * i] = random.nextDouble();
                    out[2 * i + 1] = random.nextDouble();
                }
            }
            case HALTON -> {
                double rx = random.nextDouble(), ry = random.nextDouble();
                for (int i = 0; i < count; i++) {
                    out[2 * i] = wrap(radicalInverse2(i + 1) + rx);
                    out[2 * i + 1] = wrap(radicalInverse(3, i + 1) + ry);
                }
            }
        }
        for (int i = 0; i < count; i++) place(out[2 * i], out[2 * i + 1], shape, out, 2 * i);
    }

    /**
     * Writes the Halton points {@code first + 1} to {@code first + count}, shifted by (rx, ry) modulo 1 (a
     * Cranley-Patterson rotation), mapped to {@code shape}: consecutive calls with {@code first} advancing by
     * {@code count} continue one low-discrepancy sequence, so that beams of a progressive render's successive samples
     * together cover the square or disk as evenly as one long beam.
     *
     * @param count the number of points, at least 1
     * @param first how many points of the sequence come before these, at least 0
     * @param shape the square {@code [-1/2, 1/2]^2} or the disk of diameter 1
     * @param rx the shift along x, in [0, 1)
     * @param ry the shift along y, in [0, 1)
     * @param out the array receiving x, y pairs in its first {@code 2 * count} elements
     */
    public static void haltonContinued(int count, long first, TargetShape shape, double rx, double ry, double[] out) {
        for (int i = 0; i < count; i++) {
            long index = first + i + 1;
            double u = wrap((Long.reverse(index) >>> 11) * 0x1.0p-53 + rx);
            place(u, wrap(radicalInverse3(index) + ry), shape, out, 2 * i);
        }
    }

    /**
     * As {@link #haltonContinued}, from the {@link Sobol2D} points {@code first} to {@code first + count - 1}, each
     * coordinate digitally shifted by the first 32 bits of (rx, ry).
     *
     * @param count the number of points, at least 1
     * @param first how many points of the sequence come before these, at least 0
     * @param shape the square {@code [-1/2, 1/2]^2} or the disk of diameter 1
     * @param rx the shift along x, in [0, 1)
     * @param ry the shift along y, in [0, 1)
     * @param out the array receiving x, y pairs in its first {@code 2 * count} elements
     */
    public static void sobolContinued(int count, long first, TargetShape shape, double rx, double ry, double[] out) {
        int sx = Sobol2D.shift(rx), sy = Sobol2D.shift(ry);
        for (int i = 0; i < count; i++) {
            int index = (int) (first + i);
            place(Sobol2D.x(index, sx), Sobol2D.y(index, sy), shape, out, 2 * i);
        }
    }

    /**
     * The base-3 radical inverses of the first indices, which progressive beams read over and over. Filled when the
     * class loads, which a command-line render pays for in the interpreter: 4,096 entries took a few milliseconds
     * there where 16,384 took 6 to 20.
     */
    private static final double[] RADICAL_INVERSE_3 = new double[1 << 12];

    static {
        for (int i = 0; i < RADICAL_INVERSE_3.length; i++) RADICAL_INVERSE_3[i] = radicalInverseLoop(3, i);
    }

    /** Up to this index the beams' base-3 coordinate is {@link #radicalInverseLoop}'s, as the table's entries are. */
    private static final int TABLE_ORDER_LIMIT = 1 << 14;

    private static double radicalInverse3(long i) {
        if (i < RADICAL_INVERSE_3.length) return RADICAL_INVERSE_3[(int) i];
        if (i < TABLE_ORDER_LIMIT) return radicalInverseLoop(3, (int) i);
        double result = 0, factor = 1.0 / 3;
        while (i > 0) {
            result += (i % 3) * factor;
            i /= 3;
            factor /= 3;
        }
        return result;
    }

    /**
     * Probe points for adaptive sampling of a disk of diameter 1: the centre and {@code count - 1} points evenly
     * spaced on the rim, rotated by a random angle. A straight edge crossing the disk separates two of them unless
     * it cuts off less than the circular segment between neighbouring rim points.
     *
     * @param count the number of probe points, at least 2 (the centre and {@code count - 1} rim points)
     * @param random the random stream choosing the rotation
     * @param out the array receiving x, y pairs in its first {@code 2 * count} elements
     * @throws IllegalArgumentException if {@code count} is below 2
     */
    public static void getProbeOffsets(int count, SampleStream random, double[] out) {
        if (count < 2) throw new IllegalArgumentException("probe count must be >= 2, but was " + count);
        out[0] = 0;
        out[1] = 0;
        double rotation = 2 * Math.PI * random.nextDouble();
        int rim = count - 1;
        if (rim >= RIM_COS.length) {
            for (int i = 1; i < count; i++) {
                double angle = rotation + 2 * Math.PI * (i - 1) / rim;
                out[2 * i] = 0.5 * Math.cos(angle);
                out[2 * i + 1] = 0.5 * Math.sin(angle);
            }
            return;
        }
        // The rim's points turned by the rotation: two calls of the JVM's sine and cosine instead of two per point
        // (they were a twenty-fifth of the street's render, whose adaptive lamps probe every shading point).
        double c = Math.cos(rotation), s = Math.sin(rotation);
        double[] cos = RIM_COS[rim], sin = RIM_SIN[rim];
        for (int i = 1; i < count; i++) {
            out[2 * i] = 0.5 * (c * cos[i - 1] - s * sin[i - 1]);
            out[2 * i + 1] = 0.5 * (s * cos[i - 1] + c * sin[i - 1]);
        }
    }

    /** For a rim of n points (n below the arrays' length), the cosines and sines of {@code 2 pi k / n}. */
    private static final double[][] RIM_COS = new double[33][], RIM_SIN = new double[33][];

    static {
        for (int n = 1; n < RIM_COS.length; n++) {
            RIM_COS[n] = new double[n];
            RIM_SIN[n] = new double[n];
            for (int k = 0; k < n; k++) {
                RIM_COS[n][k] = Math.cos(2 * Math.PI * k / n);
                RIM_SIN[n][k] = Math.sin(2 * Math.PI * k / n);
            }
        }
    }

    /**
     * Writes one uniformly random point of the disk of diameter 1 at {@code out[at]}, {@code out[at + 1]}.
     *
     * @param random the random stream supplying two uniform numbers
     * @param out the array receiving the point
     * @param at the index of the x coordinate in {@code out}; y goes to {@code at + 1}
     */
    public static void randomPointInDisk(SampleStream random, double[] out, int at) {
        concentricDisk(random.nextDouble(), random.nextDouble(), out, at);
    }

    /** Points in [0,1)^2, rows of near-equal length; cell centres, or jittered within cells. */
    private static void stratified(int count, SampleStream random, double[] out) {
        int rows = (int) Math.round(Math.sqrt(count));
        int base = count / rows, extra = count % rows;
        int i = 0;
        for (int r = 0; r < rows; r++) {
            int columns = base + (r < extra ? 1 : 0);
            for (int c = 0; c < columns; c++) {
                double ju = random == null ? 0.5 : random.nextDouble();
                double jv = random == null ? 0.5 : random.nextDouble();
                out[2 * i] = (c + ju) / columns;
                out[2 * i + 1] = (r + jv) / rows;
                i++;
            }
        }
    }

    /** Point (u, v) of the unit square mapped to {@code shape}, into {@code out[at]} and {@code out[at + 1]}. */
    private static void place(double u, double v, TargetShape shape, double[] out, int at) {
        if (shape == TargetShape.CIRCLE) {
            concentricDisk(u, v, out, at);
        } else {
            out[at] = u - 0.5;
            out[at + 1] = v - 0.5;
        }
    }

    /** Maps [0,1)^2 onto the disk of radius 1/2, area-preserving and stratum-preserving. */
    static void concentricDisk(double u, double v, double[] out, int at) {
        double a = 2 * u - 1, b = 2 * v - 1;
        if (a == 0 && b == 0) {
            out[at] = 0;
            out[at + 1] = 0;
            return;
        }
        // The angle is pi/4 (b/a) where |a| > |b|, pi/2 - pi/4 (a/b) elsewhere, whose cosine and sine are the sine and
        // cosine of pi/4 (a/b): both quarter angles lie within [-pi/4, pi/4]. Chosen by masks, not branches: which
        // case a sample falls in is a coin toss the CPU mispredicts half the time.
        long bitsA = Double.doubleToRawLongBits(a), bitsB = Double.doubleToRawLongBits(b);
        // All ones where |a| > |b| (magnitudes order as their bit patterns do), else zero.
        long first = ((bitsB & MAGNITUDE) - (bitsA & MAGNITUDE)) >> 63;
        double large = Double.longBitsToDouble(bitsA & first | bitsB & ~first);
        double small = Double.longBitsToDouble(bitsB & first | bitsA & ~first);
        double phi = Math.PI / 4 * (small / large);
        long cos = Double.doubleToRawLongBits(SmallAngle.cos(phi)),
                sin = Double.doubleToRawLongBits(SmallAngle.sin(phi));
        out[at] = 0.5 * large * Double.longBitsToDouble(cos & first | sin & ~first);
        out[at + 1] = 0.5 * large * Double.longBitsToDouble(sin & first | cos & ~first);
    }

    /** All bits of a double but its sign. */
    private static final long MAGNITUDE = Long.MAX_VALUE;

    /**
     * {@code x} in [0, 2) wrapped into [0, 1): {@code x - 1} where {@code x >= 1}, exact there (Sterbenz), but without
     * a branch, which a shifted sequence's points take as a coin toss (the POV-Ray comparison scene, 40 renders
     * alternated in one JVM, each order, the geometric mean of the two: 0.94-0.96x the time).
     */
    private static double wrap(double x) {
        return x - Math.floor(x);
    }

    /**
     * The van der Corput radical inverse in base 2 (by bit reversal): the first coordinate of the Halton sequence.
     *
     * @param i the index, at least 0
     * @return the radical inverse in [0, 1)
     */
    public static double radicalInverse2(int i) {
        return (Integer.reverse(i) >>> 1) * 0x1.0p-31;
    }

    /**
     * The radical inverse of {@code i} in {@code base}: the Halton sequence's coordinate of that prime base.
     *
     * @param base the base, at least 2
     * @param i the index, at least 0
     * @return the radical inverse in [0, 1)
     */
    public static double radicalInverse(int base, int i) {
        if (base == 3 && i < RADICAL_INVERSE_3.length) return RADICAL_INVERSE_3[i];
        return radicalInverseLoop(base, i);
    }

    private static double radicalInverseLoop(int base, int i) {
        double inverseBase = 1.0 / base, factor = inverseBase, result = 0;
        while (i > 0) {
            result += (i % base) * factor;
            i /= base;
            factor *= inverseBase;
        }
        return result;
    }
}
