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

    /** A file without validation poses has no validation RMS: its verdict is scored alone, and counted apart. */
    @Test
    void noValidationPoses_verdictScoredAlone_andNamedAsSuch() {
        Expected named = new Expected(Expected.Verdict.NAMED, List.of(new Expected.Claim(Expected.Family.LOST_MOTION, List.of(2))));
        var right = new DiagnosisBenchmark.Run("f", named, 0, DiagnosisBenchmark.Outcome.NAMED_RIGHT, List.of("backlash j2"), List.of(),
                Double.NaN, Double.NaN, Double.NaN, 1, 0, 0, 0);
        assertEquals(DiagnosisBenchmark.UNMEASURED, right.rmsRoute(DiagnosisBenchmark.BAR));
        org.junit.jupiter.api.Assertions.assertTrue(right.correct(DiagnosisBenchmark.BAR));
        var measured = new DiagnosisBenchmark.Run("f", named, 0, DiagnosisBenchmark.Outcome.NAMED_RIGHT, List.of("backlash j2"), List.of(),
                4.0, 1.3, Double.NaN, 1, 0, 0, 0);
        org.junit.jupiter.api.Assertions.assertFalse(measured.correct(DiagnosisBenchmark.BAR), "1.3 x the floor with validation poses fails");
        org.junit.jupiter.api.Assertions.assertTrue(DiagnosisBenchmark.markdown(List.of(right, measured)).contains("files without validation poses, verdict scored alone: 1"));
    }
}
