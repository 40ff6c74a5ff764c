package renderer.sampling;

/**
 * A small deterministic random stream (SplitMix64) that is re-seeded, never re-allocated, for every pixel, light
 * and bounce. Seeds are derived by {@link #mix} from the scene seed and the identity of what is sampled (pixel
 * index, sample index, light index...), never from the order of work, so images are bit-identical for any
 * thread count and any planning of effects.
 */
public final class SampleStream {
    private long state;

    public SampleStream() {}

    public SampleStream(long seed) {
        reset(seed);
    }

    /** Restarts the stream at {@code seed}. */
    public SampleStream reset(long seed) {
        state = seed;
        return this;
    }

    /** The next uniform double in [0, 1). */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        return finalizeHash(state);
    }

    /** A well-mixed hash of two values: the seed of a sub-stream. */
    public static long mix(long a, long b) {
        return finalizeHash(a * 0x9E3779B97F4A7C15L + finalizeHash(b + 0x632BE59BD9B4E019L));
    }

    private static long finalizeHash(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
