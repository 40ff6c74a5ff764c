package geometries;

import java.util.ArrayDeque;
import java.util.Deque;
import primitives.Util;

/**
 * A geometry compiled once so that {@link Instance}s can place it many times without copying it: the prototype
 * holds the geometry's own search structure (an {@link Accelerator} with a BVH, in the prototype's own
 * coordinates), and every instance shares it. A scene of a hundred trees made of one 10,000-triangle tree stores
 * 10,000 triangles and a hundred instances, not a million triangles (a two-level BVH, as in Embree and pbrt).
 *
 * <p>The geometry must be bounded (no planes or tubes: an instance needs a box for the scene's BVH) and must not
 * itself hold instances (one level of instancing: place the inner prototype's instances in the scene instead).
 * The prototype's BVH is built at once; a render with the BVH off searches the prototype without it too (a second,
 * flat copy made on first use), and both answer the same bit for bit.
 */
public final class Prototype {
    private final String name;
    private final Intersectable geometry;
    final Accelerator accelerator;
    /** The same geometry searched without a BVH, for renders with the BVH off; made on first use. */
    private volatile Accelerator bruteForce;

    final BoundingBox bounds;
    /** Whether any surface of the prototype may let light through (shadow rays then look past it). */
    final boolean mayTransmit;

    /**
     * Compiles {@code geometry} for instancing, under the name "prototype".
     *
     * @param geometry the geometry to place many times: bounded, holding no instances; not null
     */
    public Prototype(Intersectable geometry) {
        this("prototype", geometry);
    }

    /**
     * Compiles {@code geometry} for instancing.
     *
     * @param name a name for messages and scene files; not null
     * @param geometry the geometry to place many times: bounded, holding no instances; not null
     * @throws IllegalArgumentException if the geometry is empty, unbounded or holds an instance
     */
    public Prototype(String name, Intersectable geometry) {
        this.name = Util.requireNonNull(name, "prototype name");
        this.geometry = Util.requireNonNull(geometry, "prototype geometry");
        rejectNestedInstances(name, geometry);
        accelerator = Accelerator.build(geometry, true);
        if (accelerator.boundedPrimitiveCount() == 0 && accelerator.unboundedPrimitiveCount() == 0) {
            throw new IllegalArgumentException("prototype '" + name + "' is empty: give it at least one geometry");
        }
        bounds = accelerator.getBoundingBox();
        if (bounds == null) {
            throw new IllegalArgumentException("prototype '" + name + "' is unbounded (it holds a plane or a tube):"
                    + " only bounded geometry can be instanced");
        }
        mayTransmit = accelerator.mayTransmit();
    }

    /** The search structure for a query of a scene searched with or without BVHs. */
    Accelerator search(boolean withoutBvh) {
        if (!withoutBvh) return accelerator;
        Accelerator flat = bruteForce;
        if (flat == null) {
            synchronized (this) {
                flat = bruteForce;
                if (flat == null) bruteForce = flat = Accelerator.build(geometry, false);
            }
        }
        return flat;
    }

    private static void rejectNestedInstances(String name, Intersectable geometry) {
        Deque<Intersectable> open = new ArrayDeque<>();
        open.add(geometry);
        while (!open.isEmpty()) {
            Intersectable g = open.pop();
            if (g instanceof Instance inner) {
                throw new IllegalArgumentException("prototype '" + name + "' holds an instance of '"
                        + inner.prototype().name() + "': instances cannot be nested (one level of instancing);"
                        + " place the inner prototype's instances in the scene instead");
            }
            if (g instanceof Geometries group) open.addAll(group.getMembers());
        }
    }

    /**
     * The prototype's name.
     *
     * @return the name given at construction
     */
    public String name() {
        return name;
    }

    /**
     * The geometry placed by the instances, in the prototype's own coordinates.
     *
     * @return the geometry (shared: changing its materials changes every instance)
     */
    public Intersectable geometry() {
        return geometry;
    }

    /**
     * The bounds of the geometry in its own coordinates.
     *
     * @return the bounding box
     */
    public BoundingBox bounds() {
        return bounds;
    }

    /**
     * Primitives stored once for all instances (triangles, spheres...).
     *
     * @return the number of primitives of the prototype's search structure
     */
    public int primitiveCount() {
        return accelerator.boundedPrimitiveCount();
    }

    /**
     * Bytes of the prototype's search structure, stored once whatever the number of instances.
     *
     * @return the size in bytes
     */
    public long bytes() {
        return accelerator.bytes();
    }

    @Override
    public String toString() {
        return "Prototype[" + name + ", " + primitiveCount() + " primitives]";
    }
}
