package renderer;

import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Prototype;
import java.util.ArrayList;
import java.util.List;
import lighting.LightSource;
import primitives.Material;
import scene.Scene;

/**
 * What a render simulates, decided once from the scene and the settings, with the reason for everything it
 * leaves out: no reflection rays when no material reflects, no refraction rays when nothing is transparent, no
 * glossy beams without rough mirrors or glass, hard shadows for lights without radius, no shadow rays at all in a
 * scene whose only surface is flat (it cannot shadow itself). Per shading point the tracer further skips shadow
 * rays toward lights behind the surface, outside a spot's beam or beyond a light's range, and from surfaces with
 * no diffuse or specular response.
 *
 * <p>With planning off every flag is true: the tracer fires the skipped rays anyway and multiplies them by zero,
 * which proves that planning changes the cost and never the image.
 */
public final class EffectPlan {
    final boolean planning;
    final boolean reflection;
    final boolean refraction;
    final boolean glossy;
    final boolean shadows;
    /** Display steps of direct light a camera sample may leave out (0: exact); see RenderSettings#lightCutoff. */
    final double lightCutoff;

    private final List<String> simulated = new ArrayList<>();
    private final List<String> skipped = new ArrayList<>();

    private EffectPlan(Scene scene, RenderSettings settings) {
        planning = settings.planEffects();
        MaterialSurvey survey = new MaterialSurvey();
        survey.visit(scene.geometries);

        boolean reflects = survey.unknown || survey.reflective;
        boolean transmits = survey.unknown || survey.transparent;
        boolean rough = survey.unknown || survey.rough;
        boolean recursion = settings.maxLevel() > 1;
        reflection = decide(
                "reflection rays", reflects && recursion, !recursion ? "maxLevel is 1" : "no material has kR > 0");
        refraction = decide(
                "refraction rays", transmits && recursion, !recursion ? "maxLevel is 1" : "no material has kT > 0");
        boolean glossyBeams = settings.glossySampling().isEnabled();
        glossy = decide(
                "glossy/frosted beams of " + settings.glossySampling().getSampleCount(),
                rough && glossyBeams && (reflection || refraction),
                !glossyBeams
                        ? "glossy sampling has one sample"
                        : "no reflective or transparent material has roughness > 0");
        boolean canShadow = survey.unknown || survey.primitives > 1 || !survey.onlyFlat;
        shadows = decide(
                "shadow rays",
                canShadow && !scene.lights.isEmpty(),
                scene.lights.isEmpty() ? "the scene has no lights" : "a single flat surface cannot shadow itself");
        if (shadows) {
            int soft = 0;
            for (LightSource light : scene.lights) if (light.isSoft()) soft++;
            if (soft > 0) simulated.add("soft shadows for " + soft + " of " + scene.lights.size() + " lights");
            if (soft < scene.lights.size()) {
                skipped.add("area sampling for " + (scene.lights.size() - soft) + " lights (radius 0 or one sample)");
            }
        }
        lightCutoff = lightCutoff(settings.lightCutoff(), survey, shadows || !scene.lights.isEmpty());
        simulated.add(
                "recursion to level " + settings.maxLevel() + ", cut below attenuation " + settings.minAttenuation());
    }

    /**
     * The light cut-off in force: the setting, unless the scene could make a light's real contribution exceed the
     * unshadowed bound the cut-off relies on (a transmittance kT above 1, or geometry of unknown type).
     */
    private double lightCutoff(double setting, MaterialSurvey survey, boolean lit) {
        if (!(setting > 0) || !lit) return 0;
        String what = "lights adding less than " + setting + " display steps in all to a camera sample";
        if (survey.unknown || survey.maxKt > 1) {
            simulated.add(what + " (light cut-off off: "
                    + (survey.unknown ? "geometry of unknown type" : "a material has kT > 1") + ")");
            return 0;
        }
        skipped.add(what + " (light cut-off)");
        return setting;
    }

    /**
     * The plan for rendering {@code scene} with {@code settings}.
     *
     * @param scene the scene to render
     * @param settings the render settings
     * @return the plan: which effects are simulated and which are skipped, with reasons
     */
    public static EffectPlan of(Scene scene, RenderSettings settings) {
        return new EffectPlan(scene, settings);
    }

    private boolean decide(String effect, boolean needed, String reason) {
        if (needed) {
            simulated.add(effect);
            return true;
        }
        if (planning) {
            skipped.add(effect + " (" + reason + ")");
            return false;
        }
        simulated.add(effect + " (not needed: " + reason + "; planning off)");
        return true;
    }

    /**
     * Whether work that cannot change the image is skipped.
     *
     * @return true when planning is on
     */
    public boolean isPlanning() {
        return planning;
    }

    /**
     * The effects simulated.
     *
     * @return an unmodifiable list of the simulated effects, one description each
     */
    public List<String> simulated() {
        return List.copyOf(simulated);
    }

    /**
     * The effects skipped, each with its reason.
     *
     * @return an unmodifiable list of the skipped effects, each with its reason
     */
    public List<String> skipped() {
        return List.copyOf(skipped);
    }

    /**
     * A readable two-line summary.
     *
     * @return the lines {@code simulated: ...} and {@code skipped: ...}, plus a third when planning is off
     */
    public String describe() {
        return "simulated: " + String.join("; ", simulated) + "\nskipped:   "
                + (skipped.isEmpty() ? "nothing" : String.join("; ", skipped))
                + (planning ? "" : "\nplanning:  off (skippable rays are fired and weighted by zero)");
    }

    /** Which optical features the scene's materials use. */
    private static final class MaterialSurvey {
        boolean reflective, transparent, rough, unknown;
        /** The largest transmittance coefficient of any material (a shadow ray can gain light above 1). */
        double maxKt;

        boolean onlyFlat = true;
        int primitives;

        /** Prototypes already surveyed: a thousand instances of one model look at its materials once. */
        private final java.util.Set<Prototype> surveyed =
                java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());

        void visit(Intersectable g) {
            if (g instanceof Geometries composite) {
                for (Intersectable member : composite.getMembers()) visit(member);
                return;
            }
            if (g instanceof Instance instance) {
                // A placed copy: its surfaces are the prototype's; it may stand anywhere, so it is not flat.
                onlyFlat = false;
                primitives++;
                if (surveyed.add(instance.prototype()))
                    visit(instance.prototype().geometry());
                return;
            }
            primitives++;
            if (!(g instanceof Geometry geometry)) {
                unknown = true; // a user type: assume it may use anything
                onlyFlat = false;
                return;
            }
            if (!(g instanceof Plane || g instanceof Polygon)) onlyFlat = false;
            Material m = geometry.getMaterial();
            reflective |= m.isReflective();
            transparent |= m.isTransparent();
            rough |= m.getRoughness() > 0 && (m.isReflective() || m.isTransparent());
            maxKt = Math.max(maxKt, m.getKt().max());
        }
    }
}
