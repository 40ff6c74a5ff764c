package renderer;

import primitives.Vector;

/** The directions of ideal specular reflection and refraction (Snell's law, with total internal reflection). */
public final class Optics {
    private Optics() {}

    /**
     * Mirror direction {@code v - 2 (v.n) n}; {@code nv} is {@code v.n}.
     *
     * @param v the incoming direction
     * @param n the unit normal
     * @param nv the dot product {@code v.n}
     * @return the reflected direction
     */
    public static Vector reflect(Vector v, Vector n, double nv) {
        double f = 2 * nv;
        return new Vector(v.x - f * n.x, v.y - f * n.y, v.z - f * n.z);
    }

    /**
     * Refracted direction by Snell's law for unit {@code v} hitting a surface with outward unit normal {@code n}
     * ({@code nv} is {@code v.n}; entering when negative) and relative index {@code indexOfRefraction}. At and beyond
     * the critical angle the light is totally reflected (the grazing refracted ray at exactly the critical angle
     * would run along the surface, so it is reflected too). An index of 1 passes straight through, bit for bit.
     *
     * @param v the incoming unit direction
     * @param n the outward unit normal
     * @param nv the dot product {@code v.n}: negative when entering, positive when leaving
     * @param indexOfRefraction the index of the inside relative to the outside
     * @return the refracted unit direction, or the mirror direction on total internal reflection
     */
    public static Vector refract(Vector v, Vector n, double nv, double indexOfRefraction) {
        double[] d = new double[3];
        refract(v.x, v.y, v.z, n.x, n.y, n.z, nv, indexOfRefraction, d);
        return new Vector(d[0], d[1], d[2]);
    }

    /**
     * {@link #refract(Vector, Vector, double, double)} on coordinates, writing the direction to {@code out[0..3)}.
     *
     * @param vx the incoming direction's x component
     * @param vy the incoming direction's y component
     * @param vz the incoming direction's z component
     * @param nx the outward unit normal's x component
     * @param ny the outward unit normal's y component
     * @param nz the outward unit normal's z component
     * @param nv the dot product {@code v.n}: negative when entering, positive when leaving
     * @param indexOfRefraction the index of the inside relative to the outside
     * @param out receives the refracted (or, on total internal reflection, mirrored) direction in its first three
     *     elements
     */
    public static void refract(
            double vx,
            double vy,
            double vz,
            double nx,
            double ny,
            double nz,
            double nv,
            double indexOfRefraction,
            double[] out) {
        if (indexOfRefraction == 1) {
            out[0] = vx;
            out[1] = vy;
            out[2] = vz;
            return;
        }
        double cosI = -nv;
        double eta;
        double sign = 1;
        if (cosI > 0) {
            eta = 1 / indexOfRefraction;
        } else {
            eta = indexOfRefraction;
            cosI = -cosI;
            sign = -1;
        }
        double sin2T = eta * eta * Math.max(0, 1 - cosI * cosI);
        if (sin2T >= 1) { // total internal reflection
            double f = 2 * nv;
            out[0] = vx - f * nx;
            out[1] = vy - f * ny;
            out[2] = vz - f * nz;
            return;
        }
        double cosT = Math.sqrt(1 - sin2T);
        double f = sign * (eta * cosI - cosT);
        out[0] = eta * vx + f * nx;
        out[1] = eta * vy + f * ny;
        out[2] = eta * vz + f * nz;
    }

    /**
     * Whether light along unit {@code v} is totally reflected at a surface with normal {@code n}.
     *
     * @param v the incoming unit direction
     * @param n the outward unit normal
     * @param indexOfRefraction the index of the inside relative to the outside
     * @return true when no light is refracted
     */
    public static boolean isTotallyReflected(Vector v, Vector n, double indexOfRefraction) {
        double cosI = -v.dotProduct(n);
        double eta = cosI > 0 ? 1 / indexOfRefraction : indexOfRefraction;
        return eta * eta * Math.max(0, 1 - cosI * cosI) >= 1;
    }
}
