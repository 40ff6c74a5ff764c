package app;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Mesh;
import geometries.Sphere;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * A parked saloon car: the body is a loft of cross-sections along the car's length, built as two indexed
 * {@link Mesh}es (painted body and dark glass cabin) over one grid of shared vertices with smooth vertex normals,
 * plus cylinder wheels and emissive head and tail lights. The car points along -y or +y; its front bumper is
 * centred on the given point at road level. Units are those of the street (1 = 5 cm): 92 long, 36 wide, 30 high.
 */
final class CarModel {
    static final double LENGTH = 92, HALF_WIDTH = 18;
    private static final int STATIONS = 30;
    /** Cross-section outline, x as a fraction of the half-width, z as a position code resolved per station. */
    private static final double[] RING_X = {-0.9, -1, -1, -0.97, -0.84, -0.72, -0.36, 0.36, 0.72, 0.84, 0.97, 1, 1, 0.9
    };

    private CarModel() {}

    /**
     * The car's parts, front bumper centred at {@code front} (z = road level), pointing toward -y ({@code heading}
     * +1: the body extends toward +y) or +y (heading -1: the same car turned half round, which keeps the winding).
     */
    static Geometries build(Point front, int heading, Color paint) {
        Placement at = (x, y, z) -> new Point(front.x + heading * x, front.y + heading * y, front.z + z);
        int ring = RING_X.length;
        double[][] grid = new double[STATIONS * ring][];
        for (int i = 0; i < STATIONS; i++) {
            double s = i / (STATIONS - 1.0);
            double[] p = profile(s);
            double bottom = p[0], belt = p[1], top = p[2], halfWidth = p[3];
            double[] z = {
                bottom,
                bottom + 0.3 * (belt - bottom),
                bottom + 0.75 * (belt - bottom),
                belt,
                belt + 0.55 * (top - belt),
                top - 0.15 * (top - belt),
                top,
                top,
                top - 0.15 * (top - belt),
                belt + 0.55 * (top - belt),
                belt,
                bottom + 0.75 * (belt - bottom),
                bottom + 0.3 * (belt - bottom),
                bottom
            };
            for (int j = 0; j < ring; j++) {
                // The cabin narrows above the belt line (tumblehome).
                double taper = j >= 4 && j <= 9 ? 0.92 : 1;
                Point v = at.point(RING_X[j] * halfWidth * taper, s * LENGTH, z[j]);
                grid[i * ring + j] = new double[] {v.x, v.y, v.z};
            }
        }
        GridMesh body = new GridMesh(grid), glass = new GridMesh(grid);
        for (int i = 0; i + 1 < STATIONS; i++) {
            double s = (i + 0.5) / (STATIONS - 1);
            for (int j = 0; j < ring; j++) {
                int j1 = (j + 1) % ring;
                // Outward winding: along the length, then around the ring (left side, over the top, right side).
                int a = i * ring + j, b = i * ring + j1, c = (i + 1) * ring + j1, d = (i + 1) * ring + j;
                boolean sideWindow = (j == 3 || j == 4 || j == 8 || j == 9) && s > 0.33 && s < 0.85;
                boolean screen = (j >= 5 && j <= 7) && ((s > 0.3 && s < 0.46) || (s > 0.72 && s < 0.87));
                (sideWindow || screen ? glass : body).quad(a, b, c, d);
            }
        }
        // Close both ends with fans around their centres.
        for (int end = 0; end < 2; end++) {
            int station = end == 0 ? 0 : STATIONS - 1;
            double cx = 0, cy = 0, cz = 0;
            for (int j = 0; j < ring; j++) {
                double[] v = grid[station * ring + j];
                cx += v[0] / ring;
                cy += v[1] / ring;
                cz += v[2] / ring;
            }
            int centre = body.extraVertex(cx, cy, cz);
            for (int j = 0; j < ring; j++) {
                int a = station * ring + j, b = station * ring + (j + 1) % ring;
                // The ring runs clockwise seen from the front: reverse it there so both caps face outward.
                if (end == 0) body.triangleWithExtra(centre, b, a);
                else body.triangleWithExtra(centre, a, b);
            }
        }
        Double3 paintKd = new Double3(paint.getR() / 255, paint.getG() / 255, paint.getB() / 255);
        Material paintMaterial = new Material()
                .setKd(paintKd)
                .setKa(paintKd)
                .setKs(0.7)
                .setShininess(150)
                .setKr(0.12);
        Material glassMaterial = new Material()
                .setKd(0.03)
                .setKa(0.05)
                .setKs(0.9)
                .setShininess(300)
                .setKr(0.25);
        Geometries car = new Geometries(
                body.builder.buildSmooth().setMaterial(paintMaterial),
                glass.builder.buildSmooth().setMaterial(glassMaterial));
        Material rubber = new Material().setKd(0.08).setKa(0.05).setKs(0.2).setShininess(10);
        Material chrome = new Material().setKd(0.2).setKa(0.2).setKs(0.8).setShininess(200);
        for (double wy : new double[] {0.2 * LENGTH, 0.8 * LENGTH}) {
            for (int side = -1; side <= 1; side += 2) {
                Vector inward = new Vector(-side * heading, 0, 0);
                Ray axis = new Ray(at.point(side * (HALF_WIDTH + 0.3), wy, 6.5), inward);
                car.add(new Cylinder(6.5, axis, 5).setMaterial(rubber));
                Ray hub = new Ray(at.point(side * (HALF_WIDTH + 0.5), wy, 6.5), inward);
                car.add(new Cylinder(3.5, hub, 0.5).setMaterial(chrome));
            }
        }
        for (int side = -1; side <= 1; side += 2) {
            car.add(new Sphere(at.point(side * 12.5, 1.6, 13), 2.4)
                    .setEmission(new Color(255, 240, 205))
                    .setMaterial(new Material().setKa(0)));
            car.add(new Sphere(at.point(side * 13, LENGTH - 1.4, 16), 2)
                    .setEmission(new Color(190, 18, 14))
                    .setMaterial(new Material().setKa(0)));
        }
        return car;
    }

    /**
     * Bottom, belt line, top and half-width of the body at fraction {@code s} of the length from the front: a
     * rounded nose, bonnet, windscreen, roof, rear window, boot and rounded tail.
     */
    private static double[] profile(double s) {
        double top = interpolate(s, new double[] {0, 0.04, 0.12, 0.3, 0.46, 0.72, 0.87, 0.96, 1}, new double[] {
            12, 17, 18.5, 19.5, 29.5, 29, 20.5, 19.5, 15
        });
        double bottom = interpolate(s, new double[] {0, 0.06, 0.94, 1}, new double[] {7, 4.5, 4.5, 8});
        double belt = Math.min(top, interpolate(s, new double[] {0, 0.3, 0.87, 1}, new double[] {12, 19.5, 20.5, 15}));
        // A superellipse plan view: full width in the middle, rounded corners at both ends.
        double u = Math.abs(2 * s - 1);
        double halfWidth = HALF_WIDTH * Math.pow(1 - Math.pow(u, 6), 1 / 6.0);
        return new double[] {bottom, belt, top, Math.max(halfWidth, 0.55 * HALF_WIDTH)};
    }

    private static double interpolate(double s, double[] at, double[] value) {
        for (int k = 1; k < at.length; k++) {
            if (s <= at[k]) {
                double f = (s - at[k - 1]) / (at[k] - at[k - 1]);
                // Smoothstep between key values, so the profile has no kinks at the keys.
                f = f * f * (3 - 2 * f);
                return value[k - 1] + f * (value[k] - value[k - 1]);
            }
        }
        return value[value.length - 1];
    }

    /** Car coordinates (x across, y from the front bumper backward, z up) to scene points. */
    private interface Placement {
        Point point(double x, double y, double z);
    }

    /** A mesh over part of a shared vertex grid: grid vertices are copied in only when a triangle uses them. */
    private static final class GridMesh {
        final MeshBuilder builder = new MeshBuilder();
        private final double[][] grid;
        private final int[] index;

        GridMesh(double[][] grid) {
            this.grid = grid;
            this.index = new int[grid.length];
            java.util.Arrays.fill(index, -1);
        }

        int vertex(int g) {
            if (index[g] < 0) index[g] = builder.vertex(grid[g][0], grid[g][1], grid[g][2]);
            return index[g];
        }

        void quad(int a, int b, int c, int d) {
            builder.quad(vertex(a), vertex(b), vertex(c), vertex(d));
        }

        int extraVertex(double x, double y, double z) {
            return builder.vertex(x, y, z);
        }

        void triangleWithExtra(int extra, int a, int b) {
            builder.triangle(extra, vertex(a), vertex(b));
        }
    }
}
