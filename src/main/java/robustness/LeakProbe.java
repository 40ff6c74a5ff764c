package robustness;

import geometries.Accelerator;
import geometries.Geometries;
import geometries.HitRecord;
import geometries.Mesh;
import geometries.Meshes;
import java.util.SplittableRandom;
import primitives.Point;
import primitives.Ray;

/**
 * Measures light leaking through a closed mesh: rays from random points inside a subdivided icosphere aimed
 * exactly at its vertices and at points on its edges, where adjacent triangles meet. A watertight test hits every
 * one; a ray that escapes without a hit is a leak. The same rays are also run through a textbook Moller-Trumbore
 * test for comparison.
 */
public final class LeakProbe {
    /** Escaping rays of the watertight test and of the textbook one, out of {@code rays}. */
    public record Result(long rays, long leaks, long textbookLeaks) {}

    private LeakProbe() {}

    /**
     * @param level icosphere subdivision level
     * @param scale radius of the sphere
     * @param offset distance of its centre from the origin (along a fixed oblique direction)
     * @param raysPerTarget the number of rays aimed at each vertex and edge point
     * @param seed the random seed of the ray origins
     * @param useBvh true to search with the BVH, false by brute force
     * @return the rays traced and the leaks of the watertight and the textbook tests
     */
    public static Result run(int level, double scale, double offset, int raysPerTarget, long seed, boolean useBvh) {
        Point centre = AcneProbe.placement(offset);
        Mesh mesh = Meshes.icosphere(level).transformed(scale, centre.x, centre.y, centre.z);
        return run(mesh, centre, scale, raysPerTarget, seed, useBvh);
    }

    private static Result run(Mesh mesh, Point centre, double scale, int raysPerTarget, long seed, boolean useBvh) {
        Accelerator scene = Accelerator.build(new Geometries(mesh), useBvh);
        double[] v = mesh.getVertices();
        int[] f = mesh.getIndices();
        SplittableRandom random = new SplittableRandom(seed);
        HitRecord hit = new HitRecord();
        long rays = 0, leaks = 0, textbook = 0;
        for (int t = 0; t < f.length; t += 3) {
            for (int corner = 0; corner < 3; corner++) {
                int a = 3 * f[t + corner], b = 3 * f[t + (corner + 1) % 3];
                for (int r = 0; r < raysPerTarget; r++) {
                    // Alternately a vertex and a random point of an edge.
                    double s = r % 2 == 0 ? 0 : random.nextDouble();
                    Point target = new Point(
                            v[a] + s * (v[b] - v[a]),
                            v[a + 1] + s * (v[b + 1] - v[a + 1]),
                            v[a + 2] + s * (v[b + 2] - v[a + 2]));
                    Point origin = centre.add(AcneProbe.randomUnit(random).scale(0.5 * scale * random.nextDouble()));
                    if (target.equals(origin)) continue;
                    Ray ray = new Ray(origin, target.subtract(origin));
                    rays++;
                    hit.reset();
                    if (!scene.intersect(ray, 0, Double.POSITIVE_INFINITY, hit)) leaks++;
                    if (!mollerTrumboreHitsAny(v, f, ray)) textbook++;
                }
            }
        }
        return new Result(rays, leaks, textbook);
    }

    /** The textbook test (Moller and Trumbore 1997) against every triangle: edges decided by rounded u, v. */
    static boolean mollerTrumboreHitsAny(double[] v, int[] f, Ray ray) {
        for (int t = 0; t < f.length; t += 3) {
            int a = 3 * f[t], b = 3 * f[t + 1], c = 3 * f[t + 2];
            double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
            double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
            double px = ray.dy() * e2z - ray.dz() * e2y,
                    py = ray.dz() * e2x - ray.dx() * e2z,
                    pz = ray.dx() * e2y - ray.dy() * e2x;
            double det = e1x * px + e1y * py + e1z * pz;
            if (det == 0) continue;
            double inv = 1 / det;
            double sx = ray.ox() - v[a], sy = ray.oy() - v[a + 1], sz = ray.oz() - v[a + 2];
            double u = (sx * px + sy * py + sz * pz) * inv;
            if (u < 0 || u > 1) continue;
            double qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
            double w = (ray.dx() * qx + ray.dy() * qy + ray.dz() * qz) * inv;
            if (w < 0 || u + w > 1) continue;
            if ((e2x * qx + e2y * qy + e2z * qz) * inv > 0) return true;
        }
        return false;
    }
}
