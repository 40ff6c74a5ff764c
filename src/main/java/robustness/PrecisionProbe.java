package robustness;

import geometries.Accelerator;
import geometries.Geometries;
import geometries.Geometry;
import geometries.HitRecord;
import geometries.Sphere;
import geometries.Triangle;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.SplittableRandom;
import primitives.Point;
import primitives.Ray;

/**
 * Measures how far computed hit points lie from the exact surface when the shape is far from the origin, in
 * ulps of the distance (the spacing of doubles there: no method can do better than about half an ulp). The
 * exact distance to the surface is evaluated in 100-digit decimal arithmetic.
 */
public final class PrecisionProbe {
    private static final MathContext EXACT = new MathContext(100);

    /** Largest and mean error of the hit points in ulps of the distance, and the number of hits. */
    public record Result(double maxUlps, double meanUlps, long hits, long nonFinite) {}

    private PrecisionProbe() {}

    /**
     * Measures the hit points on a unit sphere placed {@code distance} from the origin.
     *
     * @param distance the distance of the sphere's centre from the origin, in scene units
     * @param probes the number of rays shot at the sphere
     * @param seed the random seed of the rays
     * @return the largest and mean error in ulps of the distance, the hits and non-finite hits
     */
    public static Result sphere(double distance, int probes, long seed) {
        Point c = AcneProbe.placement(distance);
        Sphere sphere = new Sphere(c, 1);
        return run(sphere, c, distance, probes, seed, p -> {
            BigDecimal dx = exact(p.x).subtract(exact(c.x)), dy = exact(p.y).subtract(exact(c.y));
            BigDecimal dz = exact(p.z).subtract(exact(c.z));
            BigDecimal r =
                    dx.multiply(dx).add(dy.multiply(dy)).add(dz.multiply(dz)).sqrt(EXACT);
            return r.subtract(BigDecimal.ONE).abs().doubleValue();
        });
    }

    /**
     * Measures the hit points on the oblique test triangle placed {@code distance} from the origin.
     *
     * @param distance the distance of the triangle's centre from the origin, in scene units
     * @param probes the number of rays shot at the triangle
     * @param seed the random seed of the rays
     * @return the largest and mean error in ulps of the distance, the hits and non-finite hits
     */
    public static Result triangle(double distance, int probes, long seed) {
        Point c = AcneProbe.placement(distance);
        Triangle t = (Triangle) AcneProbe.Shape.TRIANGLE.at(c);
        Point a = t.getVertices().get(0),
                b = t.getVertices().get(1),
                d = t.getVertices().get(2);
        BigDecimal[] e1 = difference(b, a), e2 = difference(d, a);
        BigDecimal nx = e1[1].multiply(e2[2]).subtract(e1[2].multiply(e2[1]));
        BigDecimal ny = e1[2].multiply(e2[0]).subtract(e1[0].multiply(e2[2]));
        BigDecimal nz = e1[0].multiply(e2[1]).subtract(e1[1].multiply(e2[0]));
        BigDecimal length =
                nx.multiply(nx).add(ny.multiply(ny)).add(nz.multiply(nz)).sqrt(EXACT);
        return run(t, c, distance, probes, seed, p -> {
            BigDecimal[] w = difference(p, a);
            BigDecimal dot = nx.multiply(w[0]).add(ny.multiply(w[1])).add(nz.multiply(w[2]));
            return dot.divide(length, EXACT).abs().doubleValue();
        });
    }

    private static Result run(
            Geometry shape,
            Point c,
            double distance,
            int probes,
            long seed,
            java.util.function.ToDoubleFunction<Point> error) {
        Accelerator scene = Accelerator.build(new Geometries(shape), true);
        SplittableRandom random = new SplittableRandom(seed);
        HitRecord hit = new HitRecord();
        double ulp = Math.ulp(distance), max = 0, sum = 0;
        long hits = 0, nonFinite = 0;
        for (int i = 0; i < probes; i++) {
            Point eye = c.add(AcneProbe.randomUnit(random).scale(2 + 8 * random.nextDouble()));
            Point aim = c.add(AcneProbe.randomUnit(random).scale(0.4 * random.nextDouble()));
            Ray ray = new Ray(eye, aim.subtract(eye));
            hit.reset();
            if (!scene.intersect(ray, 0, Double.POSITIVE_INFINITY, hit)) continue;
            hit.complete(ray);
            if (!AcneProbe.finite(hit)) {
                nonFinite++;
                continue;
            }
            double ulps = error.applyAsDouble(hit.point()) / ulp;
            max = Math.max(max, ulps);
            sum += ulps;
            hits++;
        }
        return new Result(max, hits == 0 ? 0 : sum / hits, hits, nonFinite);
    }

    private static BigDecimal exact(double v) {
        return new BigDecimal(v);
    }

    private static BigDecimal[] difference(Point p, Point q) {
        return new BigDecimal[] {
            exact(p.x).subtract(exact(q.x)),
            exact(p.y).subtract(exact(q.y)),
            exact(p.z).subtract(exact(q.z))
        };
    }
}
