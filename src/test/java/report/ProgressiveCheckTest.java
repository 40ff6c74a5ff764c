package report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** How the progressive check reduces repeated renders of one request to its row. */
class ProgressiveCheckTest {

    private static ProgressiveCheck.Row row(double target, double budget, double measured, double seconds, long n) {
        return new ProgressiveCheck.Row(
                "shadows",
                "asked",
                target,
                budget,
                measured * 0.9,
                measured,
                measured,
                measured,
                1,
                seconds,
                n,
                2.5,
                0.6);
    }

    @Test
    void aBudgetKeepsTheRenderOfMedianErrorWithItsOwnTimeAndSamples() {
        List<ProgressiveCheck.Row> runs = List.of(
                row(0, 0.06, 3.1, 0.061, 300_000),
                row(0, 0.06, 1.9, 0.064, 390_000),
                row(0, 0.06, 2.4, 0.059, 350_000));
        ProgressiveCheck.Row m = ProgressiveCheck.median(runs);
        assertEquals(2.4, m.measured());
        assertEquals(0.059, m.seconds(), "the median render's own time, not the median time");
        assertEquals(350_000, m.samples());
        assertEquals(2.4 * 0.9, m.predicted());
        assertEquals(1.9, m.lowest());
        assertEquals(3.1, m.highest());
        assertEquals(3, m.renders());
        assertEquals("1.900-3.100 (3 renders)", ProgressiveCheck.range(m));
        assertEquals(Math.sqrt(2.4 * 2.4 - 0.6 * 0.6), m.measuredLessReference(), 1e-12, "the reference's error kept");
    }

    @Test
    void aTargetKeepsTheMedianTime() {
        List<ProgressiveCheck.Row> runs =
                List.of(row(2, 0, 2.05, 0.30, 465_018), row(2, 0, 2.05, 0.10, 465_018), row(2, 0, 2.05, 0.12, 465_018));
        ProgressiveCheck.Row m = ProgressiveCheck.median(runs);
        assertEquals(0.12, m.seconds());
        assertEquals(2.05, m.measured());
        assertFalse(m.failed(), "2.05 is within 25% of 2");
    }

    @Test
    void oneRenderIsItsOwnRow() {
        ProgressiveCheck.Row one = row(0, 1.4, 0.77, 1.39, 657_306);
        ProgressiveCheck.Row m = ProgressiveCheck.median(List.of(one));
        assertEquals(one, m);
        assertEquals("0.770 (1 render)", ProgressiveCheck.range(m));
    }

    @Test
    void theWarmUpRendersASlowRequestOnlyInItsFirstRound() {
        ProgressiveCheck.Request quick = new ProgressiveCheck.Request(2, null);
        ProgressiveCheck.Request slow = new ProgressiveCheck.Request(1, null);
        List<ProgressiveCheck.Request> rendered = new ArrayList<>();
        int rounds = ProgressiveCheck.warmUp(List.of(quick, slow), request -> {
            rendered.add(request);
            // Whether the JIT is quiet here depends on the JVM's state, so the test asks only what holds either way.
            return row(0, 0, 1, request == slow ? ProgressiveCheck.WARM_UP_ONCE_SECONDS + 1 : 0.01, 1);
        });
        assertTrue(rounds >= 1 && rounds <= ProgressiveCheck.MAX_WARM_UP_ROUNDS, rounds + " rounds");
        assertEquals(1, rendered.stream().filter(r -> r == slow).count(), "the slow request once");
        assertEquals(rounds, rendered.stream().filter(r -> r == quick).count(), "the quick request every round");
    }

    @Test
    void theWarmUpEndsAfterOneRoundWhenEveryRequestIsSlow() {
        ProgressiveCheck.Request slow = new ProgressiveCheck.Request(1, null);
        int rounds = ProgressiveCheck.warmUp(
                List.of(slow), request -> row(0, 6, 1, ProgressiveCheck.WARM_UP_ONCE_SECONDS + 1, 1));
        assertEquals(1, rounds);
    }
}
