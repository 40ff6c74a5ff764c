package renderer;

import java.util.function.LongSupplier;

/**
 * The end of a time budget, checked by the render threads as they advance pixels within a pass, so that a pass the
 * plan misjudged, or that the machine slowed down (it is shared), stops on time instead of running over: the pixels
 * it has not reached keep the samples of the passes before, and the image stays complete.
 *
 * <p>Each thread reads the clock once per {@link #CHECK_EVERY} pixels it advances (a read costs about as much as a
 * sample's bookkeeping); once one thread finds the deadline past, every thread stops.
 */
final class BudgetDeadline {
    /** Pixels a thread advances between two reads of the clock. */
    static final int CHECK_EVERY = 16;

    private final LongSupplier clock;
    private volatile long deadline;
    private volatile boolean armed, passed;

    /** A deadline not yet armed, on {@code clock} (nanoseconds, as {@link System#nanoTime}). */
    BudgetDeadline(LongSupplier clock) {
        this.clock = clock;
    }

    /** From now on, {@link #passed} turns true once the clock reaches {@code deadline}. */
    void arm(long deadline) {
        this.deadline = deadline;
        passed = false;
        armed = true;
    }

    /**
     * Whether the deadline is past, as far as the calling thread knows: it reads the clock every
     * {@link #CHECK_EVERY} calls (counted in {@code ctx}), and learns at once what another thread found.
     */
    boolean passed(TraceContext ctx) {
        if (passed) return true;
        if (!armed || --ctx.deadlineCountdown > 0) return false;
        ctx.deadlineCountdown = CHECK_EVERY;
        if (clock.getAsLong() - deadline >= 0) passed = true; // a difference: nanoTime may wrap
        return passed;
    }
}
