package geometries;

import java.util.List;

/**
 * A read-only view of one node of a {@link BVH}'s traversal tree, for inspection and tests: its bounds and either
 * the primitives of a leaf or the indices of its two to eight children. Views are numbered depth-first, so an
 * interior node's first child is the next node; the traversal itself reads the BVH's packed arrays, not these
 * views.
 *
 * @param bounds the box around everything below the node (as the parent stores it: floats rounded outward)
 * @param firstPrimitive first primitive of a leaf, in the BVH's primitive order (-1 for interior nodes)
 * @param primitiveCount primitives in a leaf (0 for interior nodes)
 * @param children view indices of an interior node's children (empty for leaves)
 */
public record BVHNode(BoundingBox bounds, int firstPrimitive, int primitiveCount, List<Integer> children) {
    /**
     * Whether this node is a leaf.
     *
     * @return true when the node holds primitives
     */
    public boolean isLeaf() {
        return primitiveCount > 0;
    }
}
