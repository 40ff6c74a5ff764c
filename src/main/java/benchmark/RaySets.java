package benchmark;

import geometries.BoundingBox;
import java.util.SplittableRandom;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** Pre-generated benchmark rays, so ray construction stays out of the measured loop. */
public final class RaySets {
    private RaySets() {}

    /**
     * One ray through the centre of each pixel of a {@code width x height} pinhole camera with the given
     * vertical field of view, in scanline order (the order a renderer's tiles would trace them).
     *
     * @param eye the camera position, origin of every ray
     * @param target the point at the image centre
     * @param up the approximate up direction; must not be parallel to {@code target - eye}
     * @param verticalFovDegrees the vertical field of view in degrees, between 0 and 180 exclusive
     * @param width the number of pixel columns
     * @param height the number of pixel rows
     * @return {@code width * height} rays, row by row from the top
     */
    public static Ray[] pinhole(Point eye, Point target, Vector up, double verticalFovDegrees, int width, int height) {
        Vector forward = target.subtract(eye).normalize();
        Vector right = forward.crossProduct(up).normalize();
        Vector cameraUp = right.crossProduct(forward);
        double halfHeight = Math.tan(Math.toRadians(verticalFovDegrees) / 2);
        double halfWidth = halfHeight * width / height;
        Ray[] rays = new Ray[width * height];
        for (int j = 0; j < height; j++) {
            double y = (1 - 2 * (j + 0.5) / height) * halfHeight;
            for (int i = 0; i < width; i++) {
                double x = (2 * (i + 0.5) / width - 1) * halfWidth;
                Vector direction = new Vector(
                        forward.x + x * right.x + y * cameraUp.x,
                        forward.y + x * right.y + y * cameraUp.y,
                        forward.z + x * right.z + y * cameraUp.z);
                rays[j * width + i] = new Ray(eye, direction);
            }
        }
        return rays;
    }

    /**
     * {@code count} rays with origins uniform in {@code box} and directions uniform on the unit sphere.
     *
     * @param box the box the origins are drawn from
     * @param count the number of rays
     * @param seed the random seed
     * @return {@code count} new rays
     */
    public static Ray[] incoherent(BoundingBox box, int count, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Ray[] rays = new Ray[count];
        for (int i = 0; i < count; i++) {
            Point origin = new Point(
                    box.minX + random.nextDouble() * (box.maxX - box.minX),
                    box.minY + random.nextDouble() * (box.maxY - box.minY),
                    box.minZ + random.nextDouble() * (box.maxZ - box.minZ));
            double z = 2 * random.nextDouble() - 1;
            double phi = 2 * Math.PI * random.nextDouble();
            double r = Math.sqrt(Math.max(0, 1 - z * z));
            Vector direction = r == 0 ? new Vector(0, 0, z) : new Vector(r * Math.cos(phi), r * Math.sin(phi), z);
            rays[i] = new Ray(origin, direction);
        }
        return rays;
    }

    /**
     * Every {@code stride}-th ray: an evenly spread sample for the slow brute-force search.
     *
     * @param rays the rays to sample from
     * @param stride the step between sampled rays, at least 1
     * @return the rays at indices 0, {@code stride}, {@code 2 * stride}, ...
     */
    public static Ray[] sample(Ray[] rays, int stride) {
        Ray[] sample = new Ray[(rays.length + stride - 1) / stride];
        for (int i = 0; i < sample.length; i++) sample[i] = rays[i * stride];
        return sample;
    }
}
