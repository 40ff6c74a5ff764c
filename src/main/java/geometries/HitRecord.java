package geometries;

import primitives.Double3;
import primitives.Point;
import primitives.Vector;

/**
 * The mutable result of a closest-hit query, reused per thread so that the hot loop allocates nothing.
 *
 * <p>An intersection query fills {@link #t}, {@link #geometry}, {@link #part} and the local coordinates
 * {@link #u}, {@link #v}; {@link Geometry#completeHit} then fills the surface data (point, normals and the bound
 * on the point's floating-point error that spawned rays are offset by). The record also owns the BVH traversal
 * stack, so one record per thread is all the per-ray state the geometry layer needs.
 */
public final class HitRecord {
    /** Distance along the (unit-direction) ray. */
    public double t = Double.POSITIVE_INFINITY;
    /** The geometry that was hit. */
    public Geometry geometry;
    /** Which part of the geometry: the triangle of a mesh or polygon fan, the cap of a cylinder. */
    public int part;
    /** Local surface coordinates: barycentrics b1, b2 for triangles. */
    public double u, v;
    /** Index of the hit primitive in the compiled scene; orders equal-distance hits deterministically. */
    int primitiveIndex = Integer.MAX_VALUE;

    /** The hit point, refined onto the surface. */
    public Point point;
    /** The unit geometric normal; outward for closed shapes, by vertex order for triangles. */
    public Vector normal;
    /** The unit shading normal (interpolated vertex normals of meshes; otherwise the geometric normal). */
    public Vector shadingNormal;
    /** Per-axis bound on the absolute floating-point error of {@link #point}. */
    public double errorX, errorY, errorZ;

    /** Traversal stack of the BVH: link and count of each postponed child, and where the ray enters its box. */
    final int[] stack = new int[2 * BVH.STACK_SIZE];

    final double[] stackEntry = new double[BVH.STACK_SIZE];
    /** Where the ray enters each child box of the node being visited. */
    final double[] entries = new double[BVH.WIDTH];

    /** Statistics: BVH nodes visited and primitives tested by queries through this record. */
    public long nodeVisits, primitiveTests;

    /** Transparent surfaces a shadow ray crossed: primitive id and kT, multiplied in id order. */
    int transparentCount;

    private int[] transparentIds = new int[8];
    Double3[] transparentKt = new Double3[8];

    void addTransparentHit(int id, Double3 kT) {
        if (transparentCount == transparentIds.length) {
            transparentIds = java.util.Arrays.copyOf(transparentIds, 2 * transparentCount);
            transparentKt = java.util.Arrays.copyOf(transparentKt, 2 * transparentCount);
        }
        transparentIds[transparentCount] = id;
        transparentKt[transparentCount++] = kT;
    }

    /** Insertion sort by primitive id (stable, so hits of one primitive keep their order); lists are tiny. */
    void sortTransparentHits() {
        for (int i = 1; i < transparentCount; i++) {
            int id = transparentIds[i];
            Double3 kT = transparentKt[i];
            int j = i - 1;
            while (j >= 0 && transparentIds[j] > id) {
                transparentIds[j + 1] = transparentIds[j];
                transparentKt[j + 1] = transparentKt[j];
                j--;
            }
            transparentIds[j + 1] = id;
            transparentKt[j + 1] = kT;
        }
    }

    /** Forgets the previous hit so the record can take a new query. */
    public HitRecord reset() {
        t = Double.POSITIVE_INFINITY;
        geometry = null;
        part = 0;
        u = 0;
        v = 0;
        primitiveIndex = Integer.MAX_VALUE;
        point = null;
        normal = null;
        shadingNormal = null;
        return this;
    }

    /** Sets the surface error bound of the hit point. */
    public void setError(double ex, double ey, double ez) {
        errorX = ex;
        errorY = ey;
        errorZ = ez;
    }
}
