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

    /**
     * The colour this surface emits on its own.
     *
     * @return the emission, black unless set
     */
    public Color getEmission() {
        return emission;
    }

    /**
     * Sets the colour this surface emits on its own (seen regardless of lights).
     *
     * @param emission the emitted colour; not null
     * @return this geometry
     */
    public Geometry setEmission(Color emission) {
        this.emission = Util.requireNonNull(emission, "emission");
        return this;
    }

    /**
     * The surface's optical properties.
     *
     * @return the material, a default material unless set
     */
    public Material getMaterial() {
        return material;
    }

    /**
     * Sets the surface's optical properties and returns this geometry.
     *
     * @param material the material; not null
     * @return this geometry
     */
    public Geometry setMaterial(Material material) {
        this.material = Util.requireNonNull(material, "material");
        return this;
    }

    /**
     * The unit outward normal at a point on the surface (the course API). The renderer uses {@link #completeHit},
     * which also knows which part of the geometry was hit.
     *
     * @param point a point on the surface
     * @return the unit outward normal there
     */
    public abstract Vector getNormal(Point point);

    /**
     * Fills the hit point ({@code hit.px, py, pz}), the geometric and shading normals and the error bound from the
     * distance and local coordinates an intersection query left in {@code hit}.
     *
     * @param ray the ray that hit this geometry
     * @param hit the record holding the distance and local coordinates; receives the surface data
     */
    public abstract void completeHit(Ray ray, HitRecord hit);
}
