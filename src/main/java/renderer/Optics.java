package renderer;

import primitives.Vector;

/** The directions of ideal specular reflection and refraction (Snell's law, with total internal reflection). */
public final class Optics {
    private Optics() {}

    /** Mirror direction {@code v - 2 (v.n) n}; {@code nv} is {@code v.n}. */
    public static Vector reflect(Vector v, Vector n, double nv) {
        double f = 2 * nv;
        return new Vector(v.x - f * n.x, v.y - f * n.y, v.z - f * n.z);
    }

    /**
     * Refracted direction by Snell's law for unit {@code v} hitting a surface with outward unit normal {@code n}
     * ({@code nv} is {@code v.n}; entering when negative) and relative index {@code indexOfRefraction}. At and beyond
     * the critical angle the light is totally reflected (the grazing refracted ray at exactly the critical angle
     * would run along the surface, so it is reflected too). An index of 1 passes straight through, bit for bit.
     */
    public static Vector refract(Vector v, Vector n, double nv, double indexOfRefraction) {
        if (indexOfRefraction == 1) return v;
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
        if (sin2T >= 1) return reflect(v, n, nv); // total internal reflection
        double cosT = Math.sqrt(1 - sin2T);
        double f = sign * (eta * cosI - cosT);
        return new Vector(eta * v.x + f * n.x, eta * v.y + f * n.y, eta * v.z + f * n.z);
    }

    /** Whether light along unit {@code v} is totally reflected at a surface with normal {@code n}. */
    public static boolean isTotallyReflected(Vector v, Vector n, double indexOfRefraction) {
        double cosI = -v.dotProduct(n);
        double eta = cosI > 0 ? 1 / indexOfRefraction : indexOfRefraction;
        return eta * eta * Math.max(0, 1 - cosI * cosI) >= 1;
    }
}
