package geometries;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import primitives.Ray;
import primitives.Util;

/**
 * A composite of intersectables, built fluently with {@link #add}. Queried directly it tests every member (brute
 * force); a render compiles it, nested composites included, into an {@link Accelerator}.
 */
public class Geometries implements Intersectable {
    private final List<Intersectable> members = new ArrayList<>();

    /** An empty composite. */
    public Geometries() {}

    /**
     * A composite of the given geometries.
     *
     * @param geometries the members, in order; none null, and not the composite itself
     * @throws IllegalArgumentException if the array or a member is null
     */
    public Geometries(Intersectable... geometries) {
        add(geometries);
    }

    /**
     * Adds geometries and returns this composite.
     *
     * @param geometries the members to add, in order; none null, and not this composite
     * @return this composite
     * @throws IllegalArgumentException if the array or a member is null, or a member is this composite
     */
    public Geometries add(Intersectable... geometries) {
        Util.requireNonNull(geometries, "geometries");
        for (int i = 0; i < geometries.length; i++) {
            if (geometries[i] == null) {
                throw new IllegalArgumentException("geometry " + i + " of " + geometries.length + " added is null");
            }
            if (geometries[i] == this) {
                throw new IllegalArgumentException("a composite cannot contain itself");
            }
        }
        Collections.addAll(members, geometries);
        return this;
    }

    /**
     * The members, in the order they were added (read-only).
     *
     * @return an unmodifiable view of the members
     */
    public List<Intersectable> getMembers() {
        return Collections.unmodifiableList(members);
    }

    /**
     * Whether the composite has no members.
     *
     * @return true when nothing was added
     */
    public boolean isEmpty() {
        return members.isEmpty();
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        boolean found = false;
        for (Intersectable member : members) {
            if (member.intersect(ray, tMin, tMax, hit)) {
                tMax = hit.t;
                found = true;
                // An instance hit earlier is no longer the closest (instances and groups set the mark themselves).
                if (!(member instanceof Instance || member instanceof Geometries)) hit.instance = null;
            }
        }
        return found;
    }

    @Override
    public boolean occludes(Ray ray, double tMin, double tMax, HitRecord scratch) {
        for (Intersectable member : members) {
            if (member.occludes(ray, tMin, tMax, scratch)) return true;
        }
        return false;
    }

    /** The union of the members' bounds; null if any member is unbounded or there are none. */
    @Override
    public BoundingBox getBoundingBox() {
        BoundingBox box = null;
        for (Intersectable member : members) {
            BoundingBox b = member.getBoundingBox();
            if (b == null) return null;
            box = box == null ? b : box.union(b);
        }
        return box;
    }
}
