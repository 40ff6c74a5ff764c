package benchmark;

import geometries.Geometries;
import geometries.Intersectable;
import geometries.Polygon;
import geometries.Sphere;
import java.util.SplittableRandom;
import primitives.Point;
import primitives.Vector;

/** Scenes of the BVH benchmark that are not a single procedural mesh. */
public final class BenchmarkScenes {
    private BenchmarkScenes() {}

    /**
     * {@code spheres} spheres and {@code quads} randomly oriented square polygons scattered over a
     * 40 x 40 x 10 block (seeded, so every call builds the same scene): a typical hand-built scene of a few
     * hundred primitives.
     *
     * @param spheres the number of spheres, radius 0.3 to 1
     * @param quads the number of square polygons, half side 0.4 to 1.6
     * @param seed the random seed of positions, sizes and orientations
     * @return a new group of the spheres and polygons
     */
    public static Intersectable spheresAndPolygons(int spheres, int quads, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Geometries scene = new Geometries();
        for (int i = 0; i < spheres; i++) {
            scene.add(new Sphere(randomPoint(random), 0.3 + 0.7 * random.nextDouble()));
        }
        for (int i = 0; i < quads; i++) {
            Point c = randomPoint(random);
            Vector u = randomDirection(random);
            Vector v = u.crossProduct(randomDirection(random)).normalize();
            double s = 0.4 + 1.2 * random.nextDouble();
            u = u.scale(s);
            v = v.scale(s);
            scene.add(new Polygon(
                    c.add(u).add(v),
                    c.add(v).add(u.scale(-1)),
                    c.add(u.scale(-1)).add(v.scale(-1)),
                    c.add(u).add(v.scale(-1))));
        }
        return scene;
    }

    private static Point randomPoint(SplittableRandom random) {
        return new Point(40 * random.nextDouble() - 20, 40 * random.nextDouble() - 20, 10 * random.nextDouble());
    }

    private static Vector randomDirection(SplittableRandom random) {
        double z = 2 * random.nextDouble() - 1;
        double phi = 2 * Math.PI * random.nextDouble();
        double r = Math.sqrt(1 - z * z);
        return new Vector(r * Math.cos(phi), r * Math.sin(phi), z);
    }
}
