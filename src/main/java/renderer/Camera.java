package renderer;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import primitives.Point;
import primitives.Ray;
import primitives.ReusableRay;
import primitives.Util;
import primitives.Vector;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * A pinhole (or thin-lens) camera that renders a scene into an image, built with {@link #getBuilder()}.
 *
 * <p>The image is split into 16 x 16 tiles taken from a shared queue by N threads (default: the available
 * processors). Every pixel's random numbers derive from the scene seed and the pixel index, so the image is
 * bit-identical for any thread count. Per pixel the camera fires one ray through the centre or, with a
 * {@link SamplingConfig}, a beam over the pixel's area averaged with a box filter (anti-aliasing), optionally
 * adaptive (recursive subdivision where corner colours differ). With an aperture, every sample becomes a beam
 * over the lens disk focused on the focal plane (depth of field).
 *
 * <p>A render can be cancelled: by interrupting the thread that called {@link #renderImage()} (or
 * {@link #renderRegion}), or by {@link #cancel()} from any thread. The render threads stop at the next row of
 * their tile, and the call throws a {@link CancellationException}; nothing is written (images are written only by
 * the separate {@code writeToImage} calls), and an interrupted caller keeps its interrupt status.
 */
public final class Camera implements Cloneable {
    private Point location;
    private Vector vTo, vUp, vRight;
    private double vpWidth, vpHeight, vpDistance;
    private int nX, nY;
    private RayTracerBase rayTracer;
    private int threads = Runtime.getRuntime().availableProcessors();
    private RenderSettings settings = RenderSettings.DEFAULT;
    private SamplingConfig antiAliasing = SamplingConfig.NONE;
    private double apertureRadius = 0;
    private double focalDistance = 0;
    private SamplingConfig apertureSampling = new SamplingConfig(16, TargetShape.CIRCLE, SamplingPattern.JITTERED);
    private ProgressListener progress;
    /** Progressive sampling toward a target error or a time budget, or null for the fixed anti-aliasing. */
    private ProgressiveSettings progressive;
    /** What the last progressive render did, or null. */
    private ProgressiveReport lastProgressive;
    /** Set by {@link #cancel()}; cleared when a render starts. */
    private volatile boolean cancelRequested;

    private ImageWriter image;
    private RenderStatistics lastStatistics;

    private Camera() {}

    /**
     * A builder for a new camera.
     *
     * @return a builder with nothing set
     */
    public static Builder getBuilder() {
        return new Builder();
    }

    // ------------------------------------------------------------------ settings users change between renders

    /**
     * Anti-aliasing: the beam of camera rays per pixel (NONE or one sample = one central ray).
     *
     * @param config the camera rays per pixel; not null
     * @return this camera
     */
    public Camera setSamplingConfig(SamplingConfig config) {
        this.antiAliasing = Util.requireNonNull(config, "sampling config");
        return this;
    }

    /**
     * Anti-aliasing: the beam of camera rays per pixel.
     *
     * @return the sampling configuration, never null
     */
    public SamplingConfig getSamplingConfig() {
        return antiAliasing;
    }

    /**
     * Render threads, at least 1. A render starts at most {@link primitives.Limits#maxThreads()} of them (4 per
     * processor, 256 in all) and one per tile: more would only add switching, and the image is the same for any
     * count.
     *
     * @param threads the number of render threads, at least 1
     * @return this camera
     * @throws IllegalArgumentException if {@code threads} is below 1
     */
    public Camera setThreads(int threads) {
        if (threads < 1) throw new IllegalArgumentException("threads must be >= 1, but was " + threads);
        this.threads = threads;
        return this;
    }

    /**
     * The number of render threads.
     *
     * @return the thread count, at least 1
     */
    public int getThreads() {
        return threads;
    }

    /**
     * Render with the BVH (true) or brute force over the same primitives (false).
     *
     * @param useBvh true for the BVH, false for brute force
     * @return this camera
     */
    public Camera setBvh(boolean useBvh) {
        settings = settings.withBvh(useBvh);
        return this;
    }

    /**
     * Replaces all render settings (acceleration, planning, recursion, shadow and glossy sampling).
     *
     * @param settings the new settings; not null
     * @return this camera
     */
    public Camera setRenderSettings(RenderSettings settings) {
        this.settings = Util.requireNonNull(settings, "render settings");
        return this;
    }

    /**
     * The render settings.
     *
     * @return the settings, never null
     */
    public RenderSettings getRenderSettings() {
        return settings;
    }

    /**
     * Depth of field: a lens of {@code apertureRadius} (0 = pinhole) focused at {@code focalDistance} along the
     * view direction.
     *
     * @param focalDistance the distance of the focal plane along the view direction, positive and finite
     * @param apertureRadius the lens radius, finite and at least 0 (0 = pinhole)
     * @return this camera
     * @throws IllegalArgumentException if a value is out of range
     */
    public Camera setDepthOfField(double focalDistance, double apertureRadius) {
        Util.requirePositive(focalDistance, "focal distance");
        this.apertureRadius = Util.requireNonNegative(apertureRadius, "aperture radius");
        this.focalDistance = focalDistance;
        return this;
    }

    /**
     * The beam of lens samples per pixel sample for depth of field.
     *
     * @param config the lens samples per pixel sample; not null
     * @return this camera
     */
    public Camera setApertureSampling(SamplingConfig config) {
        Util.requireNonNull(config, "aperture sampling");
        this.apertureSampling = config;
        return this;
    }

    /**
     * Sets the listener told about render progress.
     *
     * @param listener called once per finished tile from the render threads, or null for none
     * @return this camera
     */
    public Camera setProgressListener(ProgressListener listener) {
        this.progress = listener;
        return this;
    }

    /**
     * Samples pixels progressively toward a target error or within a time budget instead of with the fixed
     * anti-aliasing (see {@link ProgressiveSettings}); the anti-aliasing's shape and pattern are then not used.
     *
     * @param settings the target or budget, or null for the fixed anti-aliasing
     * @return this camera
     */
    public Camera setProgressive(ProgressiveSettings settings) {
        this.progressive = settings;
        return this;
    }

    /**
     * The progressive sampling settings.
     *
     * @return the settings, or null when the fixed anti-aliasing is used
     */
    public ProgressiveSettings getProgressive() {
        return progressive;
    }

    /**
     * What the last progressive render predicted and spent.
     *
     * @return the report, or null if the last render was not progressive
     */
    public ProgressiveReport getLastProgressiveReport() {
        return lastProgressive;
    }

    /**
     * Where the camera is.
     *
     * @return the camera position
     */
    public Point getLocation() {
        return location;
    }

    /**
     * The unit view direction.
     *
     * @return the view direction
     */
    public Vector getDirection() {
        return vTo;
    }

    /**
     * The unit up direction (perpendicular to the view direction).
     *
     * @return the up direction
     */
    public Vector getUp() {
        return vUp;
    }

    /**
     * The view plane's width.
     *
     * @return the width in scene units
     */
    public double getVpWidth() {
        return vpWidth;
    }

    /**
     * The view plane's height.
     *
     * @return the height in scene units
     */
    public double getVpHeight() {
        return vpHeight;
    }

    /**
     * The distance from the camera to the view plane.
     *
     * @return the distance in scene units
     */
    public double getVpDistance() {
        return vpDistance;
    }

    /**
     * The lens radius (0 for a pinhole).
     *
     * @return the aperture radius in scene units
     */
    public double getApertureRadius() {
        return apertureRadius;
    }

    /**
     * The distance of the focal plane (0 when depth of field was never set).
     *
     * @return the focal distance in scene units, or 0
     */
    public double getFocalDistance() {
        return focalDistance;
    }

    /**
     * The beam of lens samples per pixel sample for depth of field.
     *
     * @return the aperture sampling configuration
     */
    public SamplingConfig getApertureSampling() {
        return apertureSampling;
    }

    /**
     * The ray tracer that computes the colour of each ray.
     *
     * @return the ray tracer
     */
    public RayTracerBase getRayTracer() {
        return rayTracer;
    }

    /**
     * The image width.
     *
     * @return the number of pixel columns
     */
    public int getNx() {
        return nX;
    }

    /**
     * The image height.
     *
     * @return the number of pixel rows
     */
    public int getNy() {
        return nY;
    }

    /**
     * The statistics of the last render, or null before the first.
     *
     * @return the statistics, or null
     */
    public RenderStatistics getLastStatistics() {
        return lastStatistics;
    }

    /**
     * The image of the last render, or null before the first.
     *
     * @return the image, or null
     */
    public ImageWriter getImage() {
        return image;
    }

    // ------------------------------------------------------------------ rays

    /**
     * The ray from the camera through the centre of pixel (j, i): column j from the left, row i from the top.
     *
     * @param nX the number of pixel columns of the view plane
     * @param nY the number of pixel rows of the view plane
     * @param j the 0-based pixel column, from the left
     * @param i the 0-based pixel row, from the top
     * @return a new ray from the camera location through the pixel's centre
     */
    public Ray constructRay(int nX, int nY, int j, int i) {
        double u = (j - (nX - 1) / 2.0) * (vpWidth / nX);
        double v = -(i - (nY - 1) / 2.0) * (vpHeight / nY);
        return rayThrough(u, v);
    }

    /** The ray through view-plane coordinates (u right, v up) from the pinhole. */
    private Ray rayThrough(double u, double v) {
        return rayThrough(u, v, new ReusableRay());
    }

    /** Points {@code ray} from the pinhole through view-plane coordinates (u right, v up). */
    Ray rayThrough(double u, double v, ReusableRay ray) {
        double dx = vpDistance * vTo.x + u * vRight.x + v * vUp.x;
        double dy = vpDistance * vTo.y + u * vRight.y + v * vUp.y;
        double dz = vpDistance * vTo.z + u * vRight.z + v * vUp.z;
        return ray.set(location.x, location.y, location.z, dx, dy, dz);
    }

    /** The unit vector to the right in the view plane (direction x up). */
    Vector right() {
        return vRight;
    }

    // ------------------------------------------------------------------ rendering

    /**
     * Renders the scene into a new image; statistics are in {@link #getLastStatistics()}.
     *
     * @return this camera
     * @throws IllegalStateException before any work, if the render would not fit the heap ({@link RenderMemory})
     * @throws CancellationException if the render was cancelled (see the class description)
     */
    public Camera renderImage() {
        RenderMemory.check(this, nX, nY);
        ImageWriter target = new ImageWriter("render", nX, nY);
        lastStatistics = render(0, 0, nX, nY, target::writePixel);
        image = target;
        return this;
    }

    /**
     * Renders only the pixels of a rectangle of the image: columns {@code x0 .. x0 + width - 1} and rows
     * {@code y0 .. y0 + height - 1}. Every pixel is bit-identical to the same pixel of {@link #renderImage()}
     * (its random numbers derive from the scene seed and the pixel's index in the whole image), so regions
     * rendered anywhere, in any order, any number of times, stitch with {@link ImageWriter#writeRegion} into
     * exactly the image that {@code renderImage()} gives. This is how a render is split across machines.
     *
     * <p>Statistics of this region are in {@link #getLastStatistics()}; {@link #getImage()} is not changed.
     *
     * @param x0 the 0-based leftmost column
     * @param y0 the 0-based top row
     * @param width the number of columns, at least 1
     * @param height the number of rows, at least 1
     * @return the rendered pixels
     * @throws IllegalArgumentException if the rectangle is empty or not inside the image
     */
    public ImageRegion renderRegion(int x0, int y0, int width, int height) {
        if (progressive != null) {
            throw new IllegalStateException("progressive sampling plans its samples over the whole image, so a region"
                    + " would not match the same pixels of renderImage(): render whole images, or use fixed"
                    + " anti-aliasing");
        }
        RenderMemory.check(this, width, height);
        ImageRegion region = new ImageRegion(x0, y0, width, height, nX, nY);
        lastStatistics = render(x0, y0, width, height, region::writePixel);
        return region;
    }

    /** Where rendered pixels go, in image coordinates; called from the render threads, for distinct pixels. */
    @FunctionalInterface
    private interface PixelSink {
        void write(int x, int y, double red, double green, double blue);
    }

    /**
     * Cancels the render in progress on this camera, if any: its render threads stop at the next row of their tile
     * and the rendering call throws a {@link CancellationException}. Safe from any thread (a shutdown hook, a UI).
     */
    public void cancel() {
        cancelRequested = true;
    }

    /** Renders a rectangle of the image in 16 x 16 tiles on the render threads into {@code sink}. */
    private RenderStatistics render(int x0, int y0, int width, int height, PixelSink sink) {
        long start = System.nanoTime();
        cancelRequested = false;
        lastProgressive = null;
        rayTracer.prepare(settings);
        double preparation = rayTracer.preparationSeconds();
        PixelSampler pixels = new PixelSampler(this);
        int workers = RenderMemory.workers(this, width, height);
        List<TraceContext> contexts = new ArrayList<>();
        for (int w = 0; w < workers; w++) contexts.add(new TraceContext());
        if (progressive == null) {
            tiles().run(x0, y0, width, height, contexts, (x, y, ctx) -> {
                pixels.render(x, y, ctx);
                sink.write(x, y, ctx.red, ctx.green, ctx.blue);
            });
        } else {
            renderProgressively(pixels, contexts, start, sink);
        }

        RayCounters rays = new RayCounters();
        long visits = 0, tests = 0;
        for (TraceContext ctx : contexts) {
            rays.add(ctx.counters);
            visits += ctx.nodeVisits();
            tests += ctx.primitiveTests();
        }
        double wall = (System.nanoTime() - start) * 1e-9;
        return new RenderStatistics(
                wall, preparation, workers, (long) width * height, rays, visits, tests, rayTracer.describePlan());
    }

    /** The render threads' tile loop, stopping when {@link #cancel()} is called. */
    private TileRunner tiles() {
        return new TileRunner(progress, () -> cancelRequested);
    }

    /** Progressive passes over the whole image (see {@link ProgressiveSampler}), then the pixels into the sink. */
    private void renderProgressively(PixelSampler pixels, List<TraceContext> contexts, long start, PixelSink sink) {
        ProgressiveSampler sampler = new ProgressiveSampler(pixels, progressive, nX, nY);
        TileRunner tiles = tiles();
        sampler.render(() -> tiles.run(0, 0, nX, nY, contexts, sampler::advance), start);
        double[] rgb = new double[3];
        for (int y = 0; y < nY; y++) {
            for (int x = 0; x < nX; x++) {
                sampler.mean(x, y, rgb);
                sink.write(x, y, rgb[0], rgb[1], rgb[2]);
            }
        }
        lastProgressive = sampler.report();
    }

    /**
     * Writes the last rendered image to {@code images/<name>.png} and returns its path.
     *
     * @param name the file name without extension; may contain sub-folders, not ".."
     * @return the absolute path of the written file
     * @throws IllegalStateException if nothing has been rendered yet
     */
    public Path writeToImage(String name) {
        if (image == null) throw new IllegalStateException("renderImage() must be called before writeToImage()");
        ImageWriter named = new ImageWriter(name, nX, nY);
        for (int y = 0; y < nY; y++) for (int x = 0; x < nX; x++) named.writePixel(x, y, image.getPixel(x, y));
        return named.writeToImage();
    }

    /**
     * Writes the last rendered image as PNG to {@code file}.
     *
     * @param file the PNG file to create or replace
     * @return the absolute path of the written file
     * @throws IllegalStateException if nothing has been rendered yet
     */
    public Path writeToImage(Path file) {
        if (image == null) throw new IllegalStateException("renderImage() must be called before writeToImage()");
        return image.writeToImage(file);
    }

    @Override
    protected Camera clone() {
        try {
            return (Camera) super.clone();
        } catch (CloneNotSupportedException e) {
            throw new AssertionError(e);
        }
    }

    /** Builds a {@link Camera}, validating every setting; build() reports what is missing. */
    public static final class Builder {
        private final Camera camera = new Camera();

        private Builder() {}

        /**
         * Sets where the camera is.
         *
         * @param location the camera position; not null
         * @return this builder
         */
        public Builder setLocation(Point location) {
            camera.location = Util.requireNonNull(location, "camera location");
            return this;
        }

        /**
         * The view direction {@code to} and the up direction; up need not be exactly perpendicular (its component
         * along {@code to} is removed) but must not be parallel to it.
         *
         * @param to the view direction, any length; not null
         * @param up the approximate up direction, any length; not null
         * @return this builder
         * @throws IllegalArgumentException if a direction is null or {@code up} is parallel to {@code to}
         */
        public Builder setDirection(Vector to, Vector up) {
            Util.requireNonNull(to, "camera direction 'to'");
            Util.requireNonNull(up, "camera direction 'up'");
            Vector t = to.normalize();
            Vector u = up.normalize();
            double along = u.dotProduct(t);
            double px = u.x - along * t.x, py = u.y - along * t.y, pz = u.z - along * t.z;
            if (Math.sqrt(px * px + py * py + pz * pz) < 1e-9) {
                throw new IllegalArgumentException(
                        "camera 'up' " + up + " must not be parallel to the view direction " + to);
            }
            camera.vTo = t;
            camera.vUp = new Vector(px, py, pz).normalize();
            camera.vRight = camera.vTo.crossProduct(camera.vUp).normalize();
            return this;
        }

        /**
         * Looks at {@code target} from the location (set the location first) with the given up direction.
         *
         * @param target the point at the image centre, different from the location; not null
         * @param up the approximate up direction, not parallel to the view; not null
         * @return this builder
         * @throws IllegalStateException if the location is not set yet
         * @throws IllegalArgumentException if {@code target} is null or equals the location, or {@code up} is parallel
         *     to the view
         */
        public Builder setDirection(Point target, Vector up) {
            Util.requireNonNull(target, "camera target");
            if (camera.location == null) {
                throw new IllegalStateException("set the camera location before aiming it at a target point");
            }
            if (target.equals(camera.location)) {
                throw new IllegalArgumentException("camera target " + target + " must differ from its location");
            }
            return setDirection(target.subtract(camera.location), up);
        }

        /**
         * Looks at {@code target} with +Y as up (or +Z when looking straight along Y).
         *
         * @param target the point at the image centre, different from the location; not null
         * @return this builder
         * @throws IllegalStateException if the location is not set yet
         */
        public Builder setDirection(Point target) {
            Util.requireNonNull(target, "camera target");
            if (camera.location == null) {
                throw new IllegalStateException("set the camera location before aiming it at a target point");
            }
            Vector to = target.subtract(camera.location).normalize();
            return setDirection(to, Math.abs(to.y) > 0.999999 ? Vector.AXIS_Z : Vector.AXIS_Y);
        }

        /**
         * View-plane width and height, in scene units.
         *
         * @param width the view plane width, positive and finite
         * @param height the view plane height, positive and finite
         * @return this builder
         */
        public Builder setVpSize(double width, double height) {
            Util.requirePositive(width, "view plane width");
            camera.vpHeight = Util.requirePositive(height, "view plane height");
            camera.vpWidth = width;
            return this;
        }

        /**
         * Distance from the camera to the view plane.
         *
         * @param distance the view plane distance, positive and finite
         * @return this builder
         */
        public Builder setVpDistance(double distance) {
            camera.vpDistance = Util.requirePositive(distance, "view plane distance");
            return this;
        }

        /**
         * Image resolution in pixels.
         *
         * @param nX the number of pixel columns, at least 1
         * @param nY the number of pixel rows, at least 1
         * @return this builder
         * @throws IllegalArgumentException if a dimension is below 1
         */
        public Builder setResolution(int nX, int nY) {
            if (nX < 1 || nY < 1) {
                throw new IllegalArgumentException("resolution must be positive, but was " + nX + " x " + nY);
            }
            camera.nX = nX;
            camera.nY = nY;
            return this;
        }

        /**
         * Sets the ray tracer.
         *
         * @param rayTracer the tracer of the scene; not null
         * @return this builder
         */
        public Builder setRayTracer(RayTracerBase rayTracer) {
            camera.rayTracer = Util.requireNonNull(rayTracer, "ray tracer");
            return this;
        }

        /**
         * Sets a new ray tracer of the given type on {@code scene}.
         *
         * @param scene the scene to render; not null
         * @param type the kind of ray tracer; not null
         * @return this builder
         */
        public Builder setRayTracer(Scene scene, RayTracerType type) {
            Util.requireNonNull(scene, "scene");
            Util.requireNonNull(type, "ray tracer type");
            camera.rayTracer = switch (type) {
                case SIMPLE -> new SimpleRayTracer(scene);
            };
            return this;
        }

        /**
         * Sets the number of render threads; see {@link Camera#setThreads}.
         *
         * @param threads the number of render threads, at least 1
         * @return this builder
         */
        public Builder setThreads(int threads) {
            camera.setThreads(threads);
            return this;
        }

        /**
         * Chooses the BVH or brute force; see {@link Camera#setBvh}.
         *
         * @param useBvh true for the BVH, false for brute force
         * @return this builder
         */
        public Builder setBvh(boolean useBvh) {
            camera.setBvh(useBvh);
            return this;
        }

        /**
         * Sets all render settings; see {@link Camera#setRenderSettings}.
         *
         * @param settings the render settings; not null
         * @return this builder
         */
        public Builder setRenderSettings(RenderSettings settings) {
            camera.setRenderSettings(settings);
            return this;
        }

        /**
         * Sets the anti-aliasing; see {@link Camera#setSamplingConfig}.
         *
         * @param config the camera rays per pixel; not null
         * @return this builder
         */
        public Builder setSamplingConfig(SamplingConfig config) {
            camera.setSamplingConfig(config);
            return this;
        }

        /**
         * Sets depth of field; see {@link Camera#setDepthOfField}.
         *
         * @param focalDistance the distance of the focal plane, positive and finite
         * @param apertureRadius the lens radius, finite and at least 0 (0 = pinhole)
         * @return this builder
         */
        public Builder setDepthOfField(double focalDistance, double apertureRadius) {
            camera.setDepthOfField(focalDistance, apertureRadius);
            return this;
        }

        /**
         * Sets the lens sampling; see {@link Camera#setApertureSampling}.
         *
         * @param config the lens samples per pixel sample; not null
         * @return this builder
         */
        public Builder setApertureSampling(SamplingConfig config) {
            camera.setApertureSampling(config);
            return this;
        }

        /**
         * Sets the progress listener; see {@link Camera#setProgressListener}.
         *
         * @param listener called once per finished tile, or null for none
         * @return this builder
         */
        public Builder setProgressListener(ProgressListener listener) {
            camera.setProgressListener(listener);
            return this;
        }

        /**
         * Sets progressive sampling; see {@link Camera#setProgressive}.
         *
         * @param settings the target error or time budget, or null for the fixed anti-aliasing
         * @return this builder
         */
        public Builder setProgressive(ProgressiveSettings settings) {
            camera.setProgressive(settings);
            return this;
        }

        /**
         * The camera; fails naming the first missing setting.
         *
         * @return a new camera with the builder's settings
         * @throws IllegalStateException if a required setting is missing, or an aperture is set without a focal
         *     distance
         */
        public Camera build() {
            List<String> missing = new ArrayList<>();
            if (camera.location == null) missing.add("location (setLocation)");
            if (camera.vTo == null) missing.add("direction (setDirection)");
            if (camera.vpWidth == 0) missing.add("view plane size (setVpSize)");
            if (camera.vpDistance == 0) missing.add("view plane distance (setVpDistance)");
            if (camera.nX == 0) missing.add("resolution (setResolution)");
            if (camera.rayTracer == null) missing.add("ray tracer (setRayTracer)");
            if (!missing.isEmpty()) {
                throw new IllegalStateException("camera is missing: " + String.join(", ", missing));
            }
            if (camera.apertureRadius > 0 && camera.focalDistance == 0) {
                throw new IllegalStateException("depth of field needs a focal distance");
            }
            return camera.clone();
        }
    }
}
