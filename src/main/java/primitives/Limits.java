package primitives;

/**
 * The library's limits on what a scene may ask for, shared by every setting they bound so that each message names
 * the same number. Most are fixed; the thread limit depends on the machine.
 */
public final class Limits {
    private Limits() {}

    /**
     * Most samples of one beam: camera rays per pixel, shadow rays per light and shading point, rays of a glossy
     * or frosted beam, lens samples (2^20; a million rays for one pixel is already hours of work).
     */
    public static final int MAX_SAMPLES = 1 << 20;

    /**
     * Most primitives (triangles of meshes and polygons, spheres...) of one scene, and triangles or vertices of one
     * mesh: 2^27, so that the nine coordinates of every triangle fit one Java array.
     */
    public static final int MAX_PRIMITIVES = 1 << 27;

    /**
     * Most pixels of one image: 2^28, so that its three colour channels fit one Java array (3 x 2^28 doubles, below
     * 2^31 elements).
     */
    public static final int MAX_PIXELS = 1 << 28;

    /** Most render threads on any machine: beyond this, threads only add switching and stacks. */
    public static final int MAX_THREADS = 256;

    /** Render threads allowed per processor: enough to hide stalls, few enough not to thrash. */
    public static final int THREADS_PER_PROCESSOR = 4;

    /**
     * Most render threads on this machine: {@value #THREADS_PER_PROCESSOR} per available processor, at most
     * {@value #MAX_THREADS}. More cannot make a render faster, and the image is the same for any count.
     *
     * @return the largest thread count a scene file or the command line may ask for here
     */
    public static int maxThreads() {
        return Math.min(
                MAX_THREADS, THREADS_PER_PROCESSOR * Runtime.getRuntime().availableProcessors());
    }

    /**
     * The allowed range of thread counts in words, for messages.
     *
     * @return e.g. {@code [1, 8] (4 per processor x 2 processors, at most 256)}
     */
    public static String threadRange() {
        int processors = Runtime.getRuntime().availableProcessors();
        return "[1, " + maxThreads() + "] (" + THREADS_PER_PROCESSOR + " per processor x " + processors
                + " processors, at most " + MAX_THREADS + ")";
    }
}
