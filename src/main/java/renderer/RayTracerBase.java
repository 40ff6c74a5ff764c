package renderer;

import primitives.Color;
import primitives.Ray;
import primitives.Util;
import scene.Scene;

/**
 * The part of a renderer that decides the colour seen along a ray. A render first calls {@link #prepare} once
 * (compiling the scene for the given settings), then each thread traces rays with its own {@link TraceContext}.
 * {@link #traceRay(Ray)} is the single-ray convenience of the course API.
 */
public abstract class RayTracerBase {
    /** The scene traced. */
    protected final Scene scene;

    private TraceContext convenienceContext;

    /**
     * A tracer of {@code scene}; call {@link #prepare} before tracing.
     *
     * @param scene the scene to trace; not null
     */
    protected RayTracerBase(Scene scene) {
        this.scene = Util.requireNonNull(scene, "scene");
    }

    /**
     * The scene traced.
     *
     * @return the scene given to the constructor
     */
    public Scene getScene() {
        return scene;
    }

    /**
     * Compiles the scene for rendering with {@code settings}; must precede tracing.
     *
     * @param settings the render settings the scene is compiled for
     */
    public abstract void prepare(RenderSettings settings);

    /**
     * Whether {@link #prepare} has been called.
     *
     * @return true once the scene has been compiled
     */
    public abstract boolean isPrepared();

    /**
     * Traces {@code ray} and leaves the colour seen along it in {@code context.red}, {@code green} and
     * {@code blue}: the render loop's entry, which allocates nothing. {@code pathSeed} identifies the path (pixel
     * and sample) so that every random decision below it is reproducible whatever thread traces it.
     *
     * @param ray the ray to trace
     * @param context the calling thread's scratch state, receiving the colour
     * @param pathSeed the seed identifying the pixel and sample the path belongs to
     */
    public abstract void trace(Ray ray, TraceContext context, long pathSeed);

    /**
     * As {@link #trace}, for a ray identical to the previous one this context traced (the same pixel centre again, in
     * a progressive render): a tracer may reuse that ray's first hit and shade it with the new path's samples. The
     * colour is the one {@link #trace} would give. By default it traces again.
     *
     * @param ray the same ray as the context's previous {@link #trace}
     * @param context the calling thread's scratch state
     * @param pathSeed the seed of this path's random numbers
     */
    public void traceAgain(Ray ray, TraceContext context, long pathSeed) {
        trace(ray, context, pathSeed);
    }

    /**
     * As {@link #traceAgain} for {@code samples} consecutive samples of a progressive render's pixel half at once
     * (from the context's current sequence index): where a sample's colour depends linearly on its shadow rays, one
     * shading with every sample's shadow rays gives their mean colour, which is left in the context. Returns false,
     * having done nothing, where it cannot (the caller then samples one by one). By default it cannot.
     *
     * @param ray the same ray as the context's previous {@link #trace}
     * @param context the calling thread's scratch state
     * @param pathSeed the seed of the first sample's path
     * @param samples how many samples, at least 2
     * @return whether the samples were shaded
     */
    public boolean traceAgainBatch(Ray ray, TraceContext context, long pathSeed, int samples) {
        return false;
    }

    /**
     * Finds the first hit along {@code ray} without shading it, for the {@link #traceAgain} and
     * {@link #traceAgainBatch} calls that follow (a progressive pass's samples of one pixel centre). Returns false,
     * having done nothing, where the tracer cannot; by default it cannot.
     *
     * @param ray the camera ray
     * @param context the calling thread's scratch state
     * @return whether the first hit was found (or found missing) and kept
     */
    public boolean locate(Ray ray, TraceContext context) {
        return false;
    }

    /**
     * The colour seen along {@code ray}: {@link #trace} returning a {@link Color}.
     *
     * @param ray the ray to trace
     * @param context the calling thread's scratch state
     * @param pathSeed the seed identifying the pixel and sample the path belongs to
     * @return a new colour, unclamped
     */
    public Color traceRay(Ray ray, TraceContext context, long pathSeed) {
        trace(ray, context, pathSeed);
        return context.color();
    }

    /**
     * The colour along one ray, preparing with default settings if needed (not thread-safe).
     *
     * @param ray the ray to trace
     * @return a new colour, unclamped
     */
    public Color traceRay(Ray ray) {
        if (!isPrepared()) prepare(RenderSettings.DEFAULT);
        if (convenienceContext == null) convenienceContext = new TraceContext();
        return traceRay(ray, convenienceContext, scene.getSeed());
    }

    /**
     * A one-line description of what the last {@link #prepare} decided to simulate, for render reports.
     *
     * @return the description, empty when this tracer does not plan
     */
    public String describePlan() {
        return "";
    }

    /**
     * Seconds the last {@link #prepare} spent compiling the scene.
     *
     * @return the compile time in seconds, 0 when this tracer does not report it
     */
    public double preparationSeconds() {
        return 0;
    }
}
