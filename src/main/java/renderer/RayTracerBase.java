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
    protected final Scene scene;
    private TraceContext convenienceContext;

    protected RayTracerBase(Scene scene) {
        this.scene = Util.requireNonNull(scene, "scene");
    }

    public Scene getScene() {
        return scene;
    }

    /** Compiles the scene for rendering with {@code settings}; must precede tracing. */
    public abstract void prepare(RenderSettings settings);

    /** Whether {@link #prepare} has been called. */
    public abstract boolean isPrepared();

    /**
     * Traces {@code ray} and leaves the colour seen along it in {@code context.red}, {@code green} and
     * {@code blue}: the render loop's entry, which allocates nothing. {@code pathSeed} identifies the path (pixel
     * and sample) so that every random decision below it is reproducible whatever thread traces it.
     */
    public abstract void trace(Ray ray, TraceContext context, long pathSeed);

    /** The colour seen along {@code ray}: {@link #trace} returning a {@link Color}. */
    public Color traceRay(Ray ray, TraceContext context, long pathSeed) {
        trace(ray, context, pathSeed);
        return context.color();
    }

    /** The colour along one ray, preparing with default settings if needed (not thread-safe). */
    public Color traceRay(Ray ray) {
        if (!isPrepared()) prepare(RenderSettings.DEFAULT);
        if (convenienceContext == null) convenienceContext = new TraceContext();
        return traceRay(ray, convenienceContext, scene.getSeed());
    }

    /** A one-line description of what the last {@link #prepare} decided to simulate, for render reports. */
    public String describePlan() {
        return "";
    }

    /** Seconds the last {@link #prepare} spent compiling the scene. */
    public double preparationSeconds() {
        return 0;
    }
}
