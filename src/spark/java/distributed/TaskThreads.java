package distributed;

import org.apache.spark.TaskContext;

/** How many render threads a task uses: the cores Spark gave it ({@code spark.task.cpus}, default 1). */
final class TaskThreads {
    private TaskThreads() {}

    /** {@code spark.task.cpus} of the running task; 1 outside a task. */
    static int get() {
        TaskContext task = TaskContext.get();
        return task == null ? 1 : Math.max(1, task.cpus());
    }
}
