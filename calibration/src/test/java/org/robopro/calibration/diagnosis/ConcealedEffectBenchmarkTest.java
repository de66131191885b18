package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ConcealedEffectBenchmarkTest {
    @Test
    void run_fewSeedsPerCase_meetsTheBar() {
        int seeds = Integer.parseInt(System.getenv().getOrDefault("ROBOPRO_BENCH_SEEDS", "1"));
        ConcealedEffectBenchmark.Result r = ConcealedEffectBenchmark.run(seeds, 424242L, System.out::println);
        System.out.println(r.markdown());
        assertEquals(0, r.nullFalse(), "false effects on null cases");
        assertTrue(r.jointsRightPct() >= 95, "named right with joints: " + r.jointsRightPct());
        assertTrue(r.worstCaseMeanValRatio() <= 1.15, "validation RMS / floor: " + r.worstCaseMeanValRatio());
    }
}
