package sceneio;

import primitives.Limits;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.ProgressiveSettings;
import renderer.RayTracerType;
import renderer.RenderMemory;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;
import sceneio.model.CameraDocument;
import sceneio.model.DepthOfFieldDocument;
import sceneio.model.RenderDocument;
import sceneio.model.SamplingDocument;
import sceneio.model.SceneDocument;

/**
 * Reads a scene document's {@code "camera"} and {@code "render"} objects into a {@link Camera} over the built scene:
 * the view, the image, anti-aliasing, threads, render settings and progressive sampling, each problem reported at its
 * JSON path.
 */
final class CameraReader {
    private final DocumentValues values;

    CameraReader(DocumentValues values) {
        this.values = values;
    }

    /** The document's camera, rendering {@code scene}. */
    Camera camera(SceneDocument d, Scene scene) throws SceneFileException {
        JsonPath root = JsonPath.ROOT;
        CameraDocument c = d.camera();
        if (c == null) {
            throw values.fail(
                    root,
                    "the scene has no camera: add \"camera\": {\"location\": [x, y, z], \"lookAt\": [x, y, z],"
                            + " \"vpDistance\": d, \"vpWidth\": w, \"vpHeight\": h}");
        }
        RenderDocument r = d.render();
        if (r == null) {
            throw values.fail(root, "the scene has no render settings: add \"render\": {\"width\": w, \"height\": h}");
        }
        JsonPath at = root.field("camera");
        Camera.Builder b = Camera.getBuilder();
        Point location = values.point(at.field("location"), values.required(at, "location", c.location()));
        b.setLocation(location);
        if ((c.lookAt() == null) == (c.direction() == null)) {
            throw values.fail(at, "give exactly one of \"lookAt\" (a point to aim at) and \"direction\" (a vector)");
        }
        Vector to;
        if (c.lookAt() != null) {
            Point target = values.point(at.field("lookAt"), c.lookAt());
            if (target.equals(location)) {
                throw values.fail(at.field("lookAt"), "the camera cannot look at its own location " + location);
            }
            to = values.core(at.field("lookAt"), () -> target.subtract(location)); // may overflow for huge coordinates
        } else {
            to = values.vector(at.field("direction"), c.direction());
        }
        // Default up: +Z (the scenes' world is Z-up), or +Y when looking straight up or down.
        Vector up = c.up() != null
                ? values.vector(at.field("up"), c.up())
                : Math.abs(to.normalize().z) > 0.999999 ? Vector.AXIS_Y : Vector.AXIS_Z;
        values.core(at.field("up"), () -> b.setDirection(to, up));
        double distance = values.required(at, "vpDistance", c.vpDistance());
        double width = values.required(at, "vpWidth", c.vpWidth());
        double height = values.required(at, "vpHeight", c.vpHeight());
        values.core(at.field("vpDistance"), () -> b.setVpDistance(distance));
        // Width first with a stand-in height, so an error names the field that is wrong.
        values.core(at.field("vpWidth"), () -> b.setVpSize(width, 1));
        values.core(at.field("vpHeight"), () -> b.setVpSize(width, height));
        DepthOfFieldDocument dof = c.depthOfField();
        if (dof != null) {
            JsonPath dp = at.field("depthOfField");
            double focal = values.required(dp, "focalDistance", dof.focalDistance());
            double aperture = values.required(dp, "aperture", dof.aperture());
            values.core(dp, () -> b.setDepthOfField(focal, aperture));
            if (dof.samples() != null) {
                values.core(
                        dp.field("samples"),
                        () -> b.setApertureSampling(
                                new SamplingConfig(dof.samples(), TargetShape.CIRCLE, SamplingPattern.JITTERED)));
            }
        }

        JsonPath rp = root.field("render");
        int nX = values.required(rp, "width", r.width());
        int nY = values.required(rp, "height", r.height());
        if (nX < 1) throw values.fail(rp.field("width"), "width must be >= 1 pixel, but was " + nX);
        if (nY < 1) throw values.fail(rp.field("height"), "height must be >= 1 pixel, but was " + nY);
        if ((long) nX * nY > Limits.MAX_PIXELS) {
            throw values.fail(rp, "image of " + nX + " x " + nY + " pixels is too large (at most 2^28 pixels)");
        }
        b.setResolution(nX, nY);
        if (r.antiAliasing() != null) b.setSamplingConfig(sampling(rp.field("antiAliasing"), r.antiAliasing()));
        if (r.threads() != null) {
            int threads = r.threads();
            if (threads < 1 || threads > Limits.maxThreads()) {
                throw values.fail(
                        rp.field("threads"), "threads must be in " + Limits.threadRange() + ", but was " + threads);
            }
            b.setThreads(threads);
        }
        RenderSettings settings = RenderSettings.DEFAULT;
        if (r.bvh() != null) settings = settings.withBvh(r.bvh());
        if (r.maxLevel() != null) {
            RenderSettings s = settings;
            settings = values.core(rp.field("maxLevel"), () -> s.withRecursion(r.maxLevel(), s.minAttenuation()));
        }
        if (r.shadowPattern() != null || r.adaptiveShadows() != null) {
            settings = settings.withShadowSampling(
                    r.shadowPattern() != null ? r.shadowPattern() : settings.shadowPattern(),
                    r.adaptiveShadows() != null ? r.adaptiveShadows() : settings.adaptiveShadows());
        }
        if (r.glossySamples() != null) {
            SamplingConfig glossy = values.core(
                    rp.field("glossySamples"),
                    () -> new SamplingConfig(
                            r.glossySamples(),
                            TargetShape.CIRCLE,
                            RenderSettings.DEFAULT.glossySampling().getPattern()));
            settings = settings.withGlossySampling(glossy);
        }
        if (r.lightCutoff() != null) {
            RenderSettings s = settings;
            settings = values.core(rp.field("lightCutoff"), () -> s.withLightCutoff(r.lightCutoff()));
        }
        b.setRenderSettings(settings);
        b.setProgressive(progressive(rp, r));
        b.setRayTracer(scene, RayTracerType.SIMPLE);
        Camera camera = values.core(at, b::build);
        // Memory last: it depends on the image, the samples, the threads and the geometry together.
        values.core(rp, () -> {
            RenderMemory.check(camera, nX, nY);
            return camera;
        });
        return camera;
    }

    private SamplingConfig sampling(JsonPath at, SamplingDocument s) throws SceneFileException {
        int samples = values.required(at, "samples", s.samples());
        TargetShape shape = s.shape() != null ? s.shape() : TargetShape.RECTANGLE;
        SamplingPattern pattern = s.pattern() != null ? s.pattern() : SamplingPattern.JITTERED;
        SamplingConfig config = values.core(at.field("samples"), () -> new SamplingConfig(samples, shape, pattern));
        if (s.adaptiveThreshold() != null) {
            config = values.core(
                    at.field("adaptiveThreshold"),
                    () -> new SamplingConfig(samples, shape, pattern).adaptive(s.adaptiveThreshold()));
        }
        return config;
    }

    /** Progressive sampling from {@code targetError} or {@code timeBudget}, or null for fixed sampling. */
    private ProgressiveSettings progressive(JsonPath rp, RenderDocument r) throws SceneFileException {
        if (r.targetError() != null && r.timeBudget() != null) {
            throw values.fail(rp.field("timeBudget"), "give either \"targetError\" or \"timeBudget\", not both");
        }
        if (r.targetError() != null) {
            return values.core(rp.field("targetError"), () -> ProgressiveSettings.targetError(r.targetError()));
        }
        if (r.timeBudget() != null) {
            return values.core(rp.field("timeBudget"), () -> ProgressiveSettings.timeBudget(r.timeBudget()));
        }
        return null;
    }
}
