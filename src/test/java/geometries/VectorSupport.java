package geometries;

/**
 * Whether this test JVM can run the Vector API kernels ({@link VectorKernels}): the module is present and the CPU has
 * 256-bit vectors. Asked by reflection, so that the test classes load without the module (surefire runs some of them
 * both with and without it).
 */
final class VectorSupport {
    private VectorSupport() {}

    /** Whether the vectorized kernels run here: what {@link VectorKernels#select} should pick. */
    static boolean available() throws ReflectiveOperationException {
        if (ModuleLayer.boot().findModule("jdk.incubator.vector").isEmpty()) return false;
        Class<?> doubles = Class.forName("jdk.incubator.vector.DoubleVector");
        Object preferred = doubles.getField("SPECIES_PREFERRED").get(null);
        Class<?> species = Class.forName("jdk.incubator.vector.VectorSpecies");
        return (int) species.getMethod("vectorBitSize").invoke(preferred) >= 256;
    }
}
