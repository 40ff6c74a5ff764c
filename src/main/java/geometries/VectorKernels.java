package geometries;

import java.util.function.Supplier;

/**
 * Chooses between a kernel on the JDK's incubating Vector API and its scalar twin: the vectorized class is loaded by
 * name, and only when the JVM was started with {@code --add-modules jdk.incubator.vector}, so that without the module
 * it is never loaded; if it cannot be made (no module, no 256-bit vectors on the CPU: its constructor refuses), the
 * scalar one is used.
 */
final class VectorKernels {
    private VectorKernels() {}

    /** A new instance of the class named {@code vectorized} where it can run, else {@code scalar}'s. */
    static <T> T select(Class<T> kernel, String vectorized, Supplier<T> scalar) {
        if (ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent()) {
            try {
                return kernel.cast(
                        Class.forName(vectorized).getDeclaredConstructor().newInstance());
            } catch (ReflectiveOperationException | LinkageError e) {
                return scalar.get();
            }
        }
        return scalar.get();
    }
}
