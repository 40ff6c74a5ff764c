package geometries;

/**
 * Which small groups of primitives a BVH build makes leaves whatever the SAH says: groups of at most {@code size}
 * primitives that are all {@code filterable} (by original index; null: every primitive). Where the {@link LeafFilter}
 * tests a leaf of up to four triangles in one call (four took 32-35 ns so in JMH, against 52-65 ns one by one), a
 * split of such a group saves little (Embree's SAH prices a leaf by its blocks of four); a group holding another shape,
 * whose tests the filter does not take, is left to the SAH.
 *
 * @param size the largest group filled, 0 for the SAH alone
 * @param filterable per original primitive index, whether the filter takes it; null for all
 */
record FilledLeaves(int size, boolean[] filterable) {
    /** The SAH alone. */
    static final FilledLeaves NONE = new FilledLeaves(0, null);

    /** Whether the group {@code index[start..end)} is filled into one leaf. */
    boolean fill(int[] index, int start, int end) {
        if (end - start > size) return false;
        if (filterable != null) {
            for (int k = start; k < end; k++) if (!filterable[index[k]]) return false;
        }
        return true;
    }
}
