package distributed;

import cli.BadInputException;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;

/** Starts the Spark context of a render from the Spark properties (spark-submit's, or -D system properties). */
final class SparkContexts {
    /** Tries per task before the render fails: Spark's default on a cluster, stated so it is not left implicit. */
    static final String MAX_FAILURES = "4";

    private SparkContexts() {}

    /**
     * The configuration: {@code spark.*} system properties (spark-submit sets them from {@code --master} and
     * {@code --conf}), with {@code master} instead of {@code spark.master} when given.
     *
     * @throws BadInputException without a master
     */
    static SparkConf conf(String master) throws BadInputException {
        SparkConf conf = new SparkConf().setIfMissing("spark.app.name", "raytracer");
        if (master != null) conf.setMaster(master);
        if (!conf.contains("spark.master")) {
            throw new BadInputException("no Spark master: run through spark-submit --master ..., or give"
                    + " --master local[2,4] (2 cores, each task tried up to 4 times)");
        }
        // A failed task is tried again, up to this many times in all (in local mode, local[N,F] sets it instead).
        conf.setIfMissing("spark.task.maxFailures", MAX_FAILURES);
        return conf;
    }

    /** A started context; close it to stop Spark. */
    static JavaSparkContext open(String master) throws BadInputException {
        return new JavaSparkContext(conf(master));
    }
}
