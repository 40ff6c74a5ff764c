package geometries;

import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A shape with an appearance: emission colour and material. Subclasses provide the intersection kernels and
 * {@link #completeHit}, which turns a hit distance into a surface point refined onto the shape, its normal and a
 * bound on the point's floating-point error (the input to robust ray spawning).
 */
public abstract class Geometry implements Intersectable {
    private Color emission = Color.BLACK;
    private Material material = new Material();

    public Color getEmission() {
        return emission;
    }

    /** Sets the colour this surface emits on its own (seen regardless of lights). */
    public Geometry setEmission(Color emission) {
        this.emission = Util.requireNonNull(emission, "emission");
        return this;
    }

    public Material getMaterial() {
        return material;
    }

    public Geometry setMaterial(Material material) {
        this.material = Util.requireNonNull(material, "material");
        return this;
    }

    /**
     * The unit outward normal at a point on the surface (the course API). The renderer uses {@link #completeHit},
     * which also knows which part of the geometry was hit.
     */
    public abstract Vector getNormal(Point point);

    /**
     * Fills the hit point ({@code hit.px, py, pz}), the geometric and shading normals and the error bound from the
     * distance and local coordinates an intersection query left in {@code hit}.
     */
    public abstract void completeHit(Ray ray, HitRecord hit);
}
