package distributed;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import org.apache.spark.ExceptionFailure;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerJobEnd;
import org.apache.spark.scheduler.SparkListenerJobStart;
import org.apache.spark.scheduler.SparkListenerTaskEnd;

/**
 * Counts what Spark did while it was attached: jobs started and ended, tasks that failed and with which
 * exception. Spark delivers listener events asynchronously but in order, so after {@link #awaitJobsEnded} has
 * seen a job's end, every event of that job (its task ends included) has been counted.
 */
final class TaskEvents extends SparkListener implements AutoCloseable {
    private final JavaSparkContext spark;
    private final Semaphore jobsEnded = new Semaphore(0);
    private int jobsStarted;
    private final List<String> failedTasks = new ArrayList<>();

    private TaskEvents(JavaSparkContext spark) {
        this.spark = spark;
    }

    /** Starts counting the context's events until closed. */
    static TaskEvents attach(JavaSparkContext spark) {
        TaskEvents events = new TaskEvents(spark);
        spark.sc().addSparkListener(events);
        return events;
    }

    @Override
    public synchronized void onJobStart(SparkListenerJobStart jobStart) {
        jobsStarted++;
    }

    @Override
    public void onJobEnd(SparkListenerJobEnd jobEnd) {
        jobsEnded.release();
    }

    @Override
    public synchronized void onTaskEnd(SparkListenerTaskEnd taskEnd) {
        if (taskEnd.taskInfo().failed()) {
            failedTasks.add(
                    taskEnd.reason() instanceof ExceptionFailure f
                            ? f.className() + ": " + f.description()
                            : taskEnd.reason().toString());
        }
    }

    /** Waits (at most a minute, then fails) until {@code count} jobs have ended since attaching. */
    void awaitJobsEnded(int count) throws InterruptedException {
        assertTrue(jobsEnded.tryAcquire(count, 60, TimeUnit.SECONDS), "Spark reported " + count + " jobs ending");
        jobsEnded.release(count);
    }

    synchronized int jobsStarted() {
        return jobsStarted;
    }

    /** Each failed task attempt as "exception class: message". */
    synchronized List<String> failedTasks() {
        return List.copyOf(failedTasks);
    }

    @Override
    public void close() {
        spark.sc().removeSparkListener(this);
    }
}
