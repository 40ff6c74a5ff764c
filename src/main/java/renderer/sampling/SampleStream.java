package renderer.sampling;

/**
 * A small deterministic random stream (SplitMix64) that is re-seeded, never re-allocated, for every pixel, light
 * and bounce. Seeds are derived by {@link #mix} from the scene seed and the identity of what is sampled (pixel
 * index, sample index, light index...), never from the order of work, so images are bit-identical for any
 * thread count and any planning of effects.
 */
public final class SampleStream {
    private long state;

    /** Creates a stream with state 0; call {@link #reset(long)} before use to choose the sequence. */
    public SampleStream() {}

    /**
     * Creates a stream starting at {@code seed}.
     *
     * @param seed the initial state; the same seed always gives the same sequence
     */
    public SampleStream(long seed) {
        reset(seed);
    }

    /**
     * Restarts the stream at {@code seed}.
     *
     * @param seed the new state; the same seed always gives the same sequence
     * @return this stream
     */
    public SampleStream reset(long seed) {
        state = seed;
        return this;
    }

    /**
     * The next uniform double in [0, 1).
     *
     * @return a uniformly distributed double in [0, 1), with 53 random bits
     */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    /**
     * The next 64 random bits (SplitMix64).
     *
     * @return a uniformly distributed long over its whole range
     */
    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        return finalizeHash(state);
    }

    /**
     * A well-mixed hash of two values: the seed of a sub-stream.
     *
     * @param a the first value, typically the parent seed
     * @param b the second value, typically the index of what is sampled
     * @return the seed of the sub-stream identified by {@code a} and {@code b}
     */
    public static long mix(long a, long b) {
        return finalizeHash(a * 0x9E3779B97F4A7C15L + finalizeHash(b + 0x632BE59BD9B4E019L));
    }

    private static long finalizeHash(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
