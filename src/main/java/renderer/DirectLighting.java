package renderer;

import lighting.LightSample;

/**
 * One thread's scratch for the direct light at one shading point: per light, what it gives the point, the
 * material's response to it and its unshadowed contribution, and whether it is sampled, skipped or set aside by
 * the light cut-off; plus the occluder cache (the primitive that last blocked a shadow ray toward each light).
 */
final class DirectLighting {
    /** The light gives the point nothing, or planning skips it: no shadow rays. */
    static final byte SKIP = 0;
    /** Sampled with shadow rays and added. */
    static final byte CONTRIBUTES = 1;
    /** Sampled with shadow rays and weighted by zero (planning off: shows that skipping it changes nothing). */
    static final byte WEIGHTLESS = 2;
    /** Too faint to matter: not sampled, added at the visible fraction of the sampled lights (the light cut-off). */
    static final byte SET_ASIDE = 3;

    final LightSample[] samples;
    final byte[] state;
    /** The material's response per unit of intensity: {@code kD |n.l| + kS (-v.r)^shininess}, per channel. */
    final double[] responseR, responseG, responseB;
    /** What the light adds with nothing in the way: intensity times response. */
    final double[] unshadowedR, unshadowedG, unshadowedB;
    /** The largest channel of the unshadowed contribution times the path weight: its share of the pixel. */
    private final double[] potential;
    /** Per light: the slot of the primitive that last blocked a shadow ray toward it (-1: none). */
    final int[] occluders;
    /** Lights set aside at this point. */
    int setAside;

    private final int[] candidates;

    DirectLighting(int lights) {
        samples = new LightSample[lights];
        for (int i = 0; i < lights; i++) samples[i] = new LightSample();
        state = new byte[lights];
        responseR = new double[lights];
        responseG = new double[lights];
        responseB = new double[lights];
        unshadowedR = new double[lights];
        unshadowedG = new double[lights];
        unshadowedB = new double[lights];
        potential = new double[lights];
        occluders = new int[lights];
        java.util.Arrays.fill(occluders, -1);
        candidates = new int[lights];
    }

    int lights() {
        return state.length;
    }

    /** Records light {@code li} as sampled ({@code state}), with the response (fr, fg, fb) and the path weight. */
    void set(int li, byte state, double fr, double fg, double fb, double weight) {
        this.state[li] = state;
        LightSample ls = samples[li];
        responseR[li] = fr;
        responseG[li] = fg;
        responseB[li] = fb;
        unshadowedR[li] = ls.r * fr;
        unshadowedG[li] = ls.g * fg;
        unshadowedB[li] = ls.b * fb;
        potential[li] = weight * Math.max(unshadowedR[li], Math.max(unshadowedG[li], unshadowedB[li]));
    }

    /** The unshadowed contribution of light {@code li}, summed over the channels. */
    double sum(int li) {
        return unshadowedR[li] + unshadowedG[li] + unshadowedB[li];
    }

    /**
     * Sets aside the faintest contributing lights, faintest first, while their shares of the pixel add up to less
     * than {@code budget}; returns the budget left. Ties go to the lower light index, so the choice depends on the
     * point alone.
     */
    double setAsideFaintest(double budget) {
        int n = 0;
        for (int li = 0; li < state.length; li++) {
            if (state[li] == CONTRIBUTES && potential[li] < budget) candidates[n++] = li;
        }
        // Insertion sort by share (the candidates are few: the lights far away or seen edge-on).
        for (int i = 1; i < n; i++) {
            int c = candidates[i];
            int j = i - 1;
            while (j >= 0 && potential[candidates[j]] > potential[c]) {
                candidates[j + 1] = candidates[j];
                j--;
            }
            candidates[j + 1] = c;
        }
        for (int i = 0; i < n; i++) {
            int li = candidates[i];
            if (!(potential[li] < budget)) break;
            budget -= potential[li];
            state[li] = SET_ASIDE;
            setAside++;
        }
        return budget;
    }
}
