package distributed;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolver;

/**
 * Gives tests one local Spark context for the whole test run (starting Spark takes seconds), stopped when the run
 * ends: {@code local[2,4]} (2 cores, each task tried up to 4 times), driver on loopback, no UI. Use it with
 * {@code @ExtendWith(LocalSpark.class)} and a {@code JavaSparkContext} parameter.
 */
public final class LocalSpark implements ParameterResolver {
    /** The test configuration, also what the local-mode command sets. */
    static SparkConf conf() {
        return new SparkConf()
                .setMaster("local[2,4]")
                .setAppName("raytracer-tests")
                .set("spark.driver.host", "127.0.0.1")
                .set("spark.driver.bindAddress", "127.0.0.1")
                .set("spark.ui.enabled", "false");
    }

    @Override
    public boolean supportsParameter(ParameterContext parameter, ExtensionContext extension) {
        return parameter.getParameter().getType() == JavaSparkContext.class;
    }

    @Override
    public Object resolveParameter(ParameterContext parameter, ExtensionContext extension) {
        return extension
                .getRoot()
                .getStore(ExtensionContext.Namespace.GLOBAL)
                .getOrComputeIfAbsent(Running.class, k -> new Running(new JavaSparkContext(conf())), Running.class)
                .spark;
    }

    /** The context, stopped by JUnit when the root context (the whole run) closes. */
    private record Running(JavaSparkContext spark) implements ExtensionContext.Store.CloseableResource, AutoCloseable {
        @Override
        public void close() {
            spark.stop();
        }
    }
}
