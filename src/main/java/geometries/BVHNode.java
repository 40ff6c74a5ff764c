package geometries;

/**
 * A read-only view of one node of a {@link BVH}'s binary tree, for inspection and tests: its bounds and either the
 * primitives of a leaf or the split axis and children of an interior node. Views are numbered depth-first, so an
 * interior node's first child is the next node and only the second child's index is given (as in pbrt's
 * {@code LinearBVHNode}); the traversal itself reads the BVH's packed arrays, not these views.
 *
 * @param bounds the box around everything below the node
 * @param firstPrimitive first primitive of a leaf, in the BVH's primitive order (-1 for interior nodes)
 * @param primitiveCount primitives in a leaf (0 for interior nodes)
 * @param secondChild index of the second child of an interior node (-1 for leaves)
 * @param axis split axis of an interior node, 0 = x, 1 = y, 2 = z (-1 for leaves)
 */
public record BVHNode(BoundingBox bounds, int firstPrimitive, int primitiveCount, int secondChild, int axis) {
    public boolean isLeaf() {
        return primitiveCount > 0;
    }
}
