package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/**
 * A time budget's deadline as the render threads see it: never passed before it is armed, the clock read once per
 * {@link BudgetDeadline#CHECK_EVERY} pixels per thread, passed from the first read at or after the deadline on, for
 * every thread at once, and armed again for a new render.
 */
class BudgetDeadlineTest {
    @Test
    void threadsReadTheClockEverySixteenPixelsAndStopTogether() {
        AtomicLong now = new AtomicLong(1_000), reads = new AtomicLong();
        BudgetDeadline deadline = new BudgetDeadline(() -> {
            reads.incrementAndGet();
            return now.get();
        });
        TraceContext a = new TraceContext(), b = new TraceContext();
        for (int i = 0; i < 100; i++) assertFalse(deadline.passed(a), "not armed: no deadline");
        assertEquals(0, reads.get(), "an unarmed deadline never reads the clock");

        deadline.arm(2_000);
        assertFalse(deadline.passed(a)); // the first pixel reads the clock
        assertEquals(1, reads.get());
        for (int i = 1; i < BudgetDeadline.CHECK_EVERY; i++) assertFalse(deadline.passed(a));
        assertEquals(1, reads.get(), "no read within the next pixels");
        assertFalse(deadline.passed(b), "b's first pixel reads the clock too");
        assertEquals(2, reads.get());
        now.set(2_000); // the deadline itself counts as past
        assertTrue(deadline.passed(a), "a's next read finds the deadline");
        assertEquals(3, reads.get());
        assertTrue(deadline.passed(b), "b learns it without reading the clock");
        long before = reads.get();
        for (int i = 0; i < 100; i++) assertTrue(deadline.passed(b));
        assertEquals(before, reads.get(), "once passed, no thread reads the clock again");

        deadline.arm(5_000); // a new render
        now.set(4_000);
        for (int i = 0; i < 3 * BudgetDeadline.CHECK_EVERY; i++) assertFalse(deadline.passed(a));
    }

    @Test
    void aClockThatWrapsStillReachesTheDeadline() {
        AtomicLong now = new AtomicLong(Long.MAX_VALUE - 10);
        BudgetDeadline deadline = new BudgetDeadline(now::get);
        deadline.arm(Long.MAX_VALUE + 20); // wrapped: negative
        TraceContext ctx = new TraceContext();
        assertFalse(deadline.passed(ctx));
        now.set(Long.MAX_VALUE + 25); // past, though a smaller number than when armed
        for (int i = 1; i < BudgetDeadline.CHECK_EVERY; i++) assertFalse(deadline.passed(ctx));
        assertTrue(deadline.passed(ctx));
    }
}
