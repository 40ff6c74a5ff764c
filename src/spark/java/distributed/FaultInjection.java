package distributed;

import java.io.Serializable;
import java.util.Set;
import java.util.TreeSet;
import org.apache.spark.SparkConf;
import org.apache.spark.TaskContext;

/**
 * Makes the first attempt of chosen tasks fail, to show (and test) that Spark's retries cannot change the result:
 * the task renders its tile or frame completely and then throws, so the retry renders it a second time. Set with
 * {@code --conf spark.raytracer.failFirstAttempt=0,3} (tile indices or frame numbers); off by default.
 */
public final class FaultInjection implements Serializable {
    private static final long serialVersionUID = 1L;

    /** The Spark property that names the tiles or frames whose first attempt fails. */
    public static final String PROPERTY = "spark.raytracer.failFirstAttempt";

    /** No injected failures. */
    public static final FaultInjection NONE = new FaultInjection(Set.of());

    private final TreeSet<Integer> items;

    public FaultInjection(Set<Integer> items) {
        this.items = new TreeSet<>(items);
    }

    /** The failures named by {@link #PROPERTY} in {@code conf}, a comma-separated list of indices. */
    public static FaultInjection from(SparkConf conf) {
        String value = conf.get(PROPERTY, "").trim();
        if (value.isEmpty()) return NONE;
        TreeSet<Integer> items = new TreeSet<>();
        for (String part : value.split(",")) {
            try {
                items.add(Integer.parseInt(part.trim()));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(
                        PROPERTY + " must list tile or frame numbers separated by commas, but was '" + value + "'");
            }
        }
        return new FaultInjection(items);
    }

    /** Throws if {@code item} is chosen and this is the task's first attempt; call after rendering it. */
    public void afterRendering(String kind, int item) {
        TaskContext task = TaskContext.get();
        if (task != null && task.attemptNumber() == 0 && items.contains(item)) {
            throw new InjectedFailure("injected failure of the first attempt of " + kind + " " + item + " (" + PROPERTY
                    + "): Spark retries it");
        }
    }

    public boolean isEmpty() {
        return items.isEmpty();
    }

    @Override
    public String toString() {
        return items.toString();
    }

    /** The exception of an injected failure, so logs tell it apart from a real one. */
    public static final class InjectedFailure extends RuntimeException {
        private static final long serialVersionUID = 1L;

        InjectedFailure(String message) {
            super(message);
        }
    }
}
