package distributed;

import java.util.concurrent.atomic.AtomicInteger;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerTaskEnd;

/**
 * Counts task attempts that failed (and were retried, if the render succeeded), so a render reports them: they
 * cost time but cannot change the image. Spark delivers the events asynchronously; the count is complete once
 * the context has stopped.
 */
final class FailedAttempts extends SparkListener {
    private final AtomicInteger failed = new AtomicInteger();

    @Override
    public void onTaskEnd(SparkListenerTaskEnd taskEnd) {
        if (taskEnd.taskInfo().failed()) failed.incrementAndGet();
    }

    int count() {
        return failed.get();
    }
}
