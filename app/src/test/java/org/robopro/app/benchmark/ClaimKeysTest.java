package org.robopro.app.benchmark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robopro.world.Expected;

/** How a label's claim on several joints is scored against the diagnosis' one-effect-per-joint names. */
class ClaimKeysTest {
    @Test
    void gravityOnTwoJoints_isNamedRightByOneEffectOnEach_andWrongByOneOfThemPlusAnother() {
        var want = new LinkedHashSet<>(DiagnosisBenchmark.keys(new Expected.Claim(Expected.Family.GRAVITY_ELASTICITY, List.of(2, 3))));
        String g2 = DiagnosisBenchmark.key(Expected.Family.GRAVITY_ELASTICITY, List.of(2));
        String g3 = DiagnosisBenchmark.key(Expected.Family.GRAVITY_ELASTICITY, List.of(3));
        String g5 = DiagnosisBenchmark.key(Expected.Family.GRAVITY_ELASTICITY, List.of(5));
        assertEquals(Set.of(g2, g3), want);
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_RIGHT, DiagnosisBenchmark.score(Expected.Verdict.NAMED, want, Set.of(g2, g3), false));
        assertEquals(DiagnosisBenchmark.Outcome.LOCATED_ONLY, DiagnosisBenchmark.score(Expected.Verdict.NAMED, want, Set.of(g2), false));
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_WRONG, DiagnosisBenchmark.score(Expected.Verdict.NAMED, want, Set.of(g2, g5), false));
    }

    @Test
    void crossCoupling_staysOneClaimOnDrivenAndSource() {
        var keys = DiagnosisBenchmark.keys(new Expected.Claim(Expected.Family.CROSS_COUPLING, List.of(3, 2)));
        assertEquals(List.of(DiagnosisBenchmark.key(Expected.Family.CROSS_COUPLING, List.of(3, 2))), keys);
    }
}
