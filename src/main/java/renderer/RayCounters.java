package renderer;

/**
 * Per-thread counts of the rays fired by kind and of adaptive savings. Plain fields, no synchronisation: every
 * render thread owns one and they are summed once at the end.
 */
public final class RayCounters {
    /** Camera rays, one per sample of a pixel. */
    public long camera;
    /** Shadow rays toward lights. */
    public long shadow;
    /** Reflection rays. */
    public long reflection;
    /** Refraction rays. */
    public long refraction;
    /** Secondary rays of rough (glossy or frosted) surfaces; also counted as reflection or refraction. */
    public long glossy;
    /** Camera rays through a lens aperture (depth of field); also counted as camera rays. */
    public long depthOfField;
    /** Samples that adaptive anti-aliasing and adaptive shadows did not need to fire. */
    public long samplesSaved;
    /** Lights not sampled at a shading point because they could not matter there (the light cut-off). */
    public long lightsCutOff;
    /** Shadow rays those lights would have cost at the least (one per hard light, the probes of an adaptive disk). */
    public long shadowRaysCutOff;

    /**
     * Adds another thread's counts to these.
     *
     * @param other the counts added; unchanged
     */
    public void add(RayCounters other) {
        camera += other.camera;
        shadow += other.shadow;
        reflection += other.reflection;
        refraction += other.refraction;
        glossy += other.glossy;
        depthOfField += other.depthOfField;
        samplesSaved += other.samplesSaved;
        lightsCutOff += other.lightsCutOff;
        shadowRaysCutOff += other.shadowRaysCutOff;
    }

    /**
     * All rays fired.
     *
     * @return camera, shadow, reflection and refraction rays summed
     */
    public long total() {
        return camera + shadow + reflection + refraction;
    }
}
