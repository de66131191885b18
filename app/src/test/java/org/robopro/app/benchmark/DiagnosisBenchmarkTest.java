package org.robopro.app.benchmark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robopro.world.Expected;
import org.robopro.world.Scenario;

/**
 * The independent diagnosis benchmark at a size CI can afford: scenarios of every group (null,
 * outside, each family, a pair, sparse and noisy campaigns), one seed each, diagnosed blind from the
 * measurement text. A run is right when a named scenario is named exactly with validation RMS
 * ≤ 1.15 × the noise floor, a null one claims nothing (and reaches the same bar), an outside one is
 * located and not named. What the diagnosis does not yet achieve is listed in {@link #KNOWN_FAILURES}
 * with what it did; the test fails when any other run goes wrong (the list may only shrink) and
 * reports the known failures that now pass, so the list can be cut. It never relaxes the bar.
 */
class DiagnosisBenchmarkTest {
    static final long SEED = 7;

    static final List<String> CI = List.of(
            "null irb2000", "null irb2000, 50 poses", "null irb2000, 5 gross outliers", "null puma560",
            "transmission error j1, k 1-3", "transmission error j1, cycloidal k up to 40",
            "lost motion j1, directions recorded", "lost motion j2, directions recorded", "lost motion j2, directions not recorded",
            "thermal growth per link",
            "joint elasticity j3, masses off 30 %",
            "gear-ratio error j1", "cross-coupling j3<-j2",
            "lost motion j2 + thermal growth per link",
            "outside: bump in the angle of j3", "outside: measured point sags with reach",
            // differently formed truths: lost motion with unequal flanks; directions inferred from a joint-by-joint
            // campaign whose still joints show only read-back jitter; outside: an error depending on two joints, a drive's
            // zero moving with its temperature
            "lost motion j2, unequal flanks (gravity preload)", "lost motion j1, directions not recorded, two joints moved per pose",
            "outside: j2 error depending on j2 and j4", "outside: j2 zero moving with drive temperature",
            // outside cases once named as a family beside their fallback on this seed (instrument drift, compliance of j5)
            "outside: j3 zero creeping with time", "outside: arm bends with payload and reach",
            // every pose approached from one side: the lost motion cannot be told (nothing may be claimed); approached from
            // the other side at a fifth of the poses: named
            "lost motion j2, every pose approached from above (cannot be told)",
            "lost motion j2, j2 approached from above, a fifth of the poses from below",
            // open-world forms a clean-room simulator showed: the instrument's own errors (once named a transmission error
            // of joint 1), a dress pack pulling the wrist (once a coupling), a stiffening joint spring (once a gear), the base
            // rocking on its foundation (once a compliance of joint 2), lost motion held by gravity beside a coupling (once
            // located as a step), a bearing's wobble (couplings of joint 4)
            "outside: tracker distance and azimuth errors", "outside: dress-pack drag on the wrist",
            "joint elasticity j2 with a stiffening spring, masses off 30 %",
            "outside: base rocks on its foundation above an overturning moment",
            "lost motion j2 held on one flank by gravity + cross-coupling j5<-j4",
            "outside: bearing wobble of j3 at twice its angle");

    /** Scenario -> what the diagnosis did on the CI seed when it was last checked. */
    static final Map<String, String> KNOWN_FAILURES = Map.of(
            // Gaussian noise draws beyond the outlier detector's 5 robust sigmas (about 1 point in 65 000): the
            // diagnosis reports them, and a clean pose reported as an outlier scores the run wrong.
            "null irb2000, 50 poses", "clean at 1.11 x the floor, but training pose 24 (its noise draw 5.2 sigma) reported as an outlier",
            "lost motion j2 + thermal growth per link", "named right at 1.02 x the floor, but training pose 141 (noise draw 5.5 sigma) "
                    + "reported as an outlier",
            "lost motion j2 held on one flank by gravity + cross-coupling j5<-j4", "named right (backlash j2 held by gravity above "
                    + "67.1 N·m ± 50 %, coupling j5<-j4) at 1.08 x the floor, but 2 clean poses near the hand-over reported as "
                    + "outliers (the file's masses put the holding torque elsewhere than the arm's)");

    @Test
    void ciScenarios_giveTheRightAnswerOrAreKnownFailures() {
        List<Scenario> scenarios = CI.stream().map(Scenario::named).toList();
        // a twin is diagnosed only where the bar on the floor is missed: the verdicts are those of the full benchmark
        List<DiagnosisBenchmark.Run> runs = DiagnosisBenchmark.run(scenarios, 1, SEED, DiagnosisBenchmark.Twins.WHEN_NEEDED, System.out::println);
        System.out.println(DiagnosisBenchmark.markdown(runs));
        List<String> unexpected = new ArrayList<>(), nowPassing = new ArrayList<>();
        for (DiagnosisBenchmark.Run r : runs) {
            boolean known = KNOWN_FAILURES.containsKey(r.name());
            if (!r.correct(DiagnosisBenchmark.BAR) && !known) unexpected.add(r.line());
            if (r.correct(DiagnosisBenchmark.BAR) && known) nowPassing.add(r.name());
        }
        if (!nowPassing.isEmpty()) System.out.println("known failures that now pass (cut them from the list): " + nowPassing);
        assertEquals(List.of(), unexpected, "runs that went wrong and are not known failures");
    }

    /** The one-sided campaigns' answers belong to their own campaigns: the demo, which measures with its own, does not offer them. */
    @Test
    void oneSidedScenarios_areNotConcealedByTheDemo() {
        assertFalse(org.robopro.app.demo.Demo.concealGroups().contains(Scenario.ONE_SIDED));
        assertTrue(org.robopro.app.demo.Demo.concealGroups().contains("lost-motion"));
    }

    @Test
    void twinOfANullCampaign_isTheCampaign_sameValidationRms() {
        Scenario s = Scenario.named("null irb2000, 50 poses");
        assertEquals(s.trial(SEED).campaign().text(), s.twin(SEED).campaign().text());
        DiagnosisBenchmark.Run r = DiagnosisBenchmark.run(s, SEED, DiagnosisBenchmark.Twins.ALWAYS);
        assertEquals(r.finalRatio(), r.twinRatio(), 0.0, "the twin of a null campaign is diagnosed to the same validation RMS");
        // the run takes its own ratio for such a twin: the twin diagnosed as a case of its own ends exactly there
        var twinCase = DiagnosisBenchmark.Case.of(s.trial(SEED), s.twin(SEED)).twin();
        assertEquals(r.finalRatio(), DiagnosisBenchmark.run(twinCase, DiagnosisBenchmark.Twins.NEVER).finalRatio(), 0.0);
        assertEquals(1.0, r.toTwin(), 0.0);
        // with an effect, the twin is a different campaign that ends nearer the floor
        DiagnosisBenchmark.Run lm = DiagnosisBenchmark.run(Scenario.named("lost motion j2, 50 poses"), SEED, DiagnosisBenchmark.Twins.ALWAYS);
        assertTrue(lm.twinRatio() > 0.8 && lm.twinRatio() < 1.3 && lm.twinRatio() < lm.geoRatio(), lm.line());
        DiagnosisBenchmark.Run none = DiagnosisBenchmark.run(s, SEED, DiagnosisBenchmark.Twins.NEVER);
        assertTrue(Double.isNaN(none.twinRatio()) && none.finalRatio() == r.finalRatio(), none.line());
    }

    @Test
    void rmsBar_metOnTheFloor_orWithinFivePercentOfATwinAboveTheFloor() {
        assertEquals("floor", run(1.15, Double.NaN).rmsRoute(DiagnosisBenchmark.BAR));
        assertEquals(null, run(1.16, Double.NaN).rmsRoute(DiagnosisBenchmark.BAR));
        assertEquals("twin", run(1.18, 1.14).rmsRoute(DiagnosisBenchmark.BAR));
        assertEquals("twin", run(1.196, 1.14).rmsRoute(DiagnosisBenchmark.BAR));
        assertEquals(null, run(1.20, 1.14).rmsRoute(DiagnosisBenchmark.BAR), "5.3 % above its twin");
        assertEquals(null, run(1.16, 1.10).rmsRoute(DiagnosisBenchmark.BAR), "a twin at 1.10 x the floor does not excuse the bar");
        assertTrue(run(1.18, 1.14).correct(DiagnosisBenchmark.BAR));
        assertFalse(run(1.20, 1.14).correct(DiagnosisBenchmark.BAR));
        String md = DiagnosisBenchmark.markdown(List.of(run(1.02, 1.01), run(1.18, 1.14), run(1.3, 1.0)));
        assertTrue(md.contains("1 of 3 runs within 1.15 × the floor, 1 more within 1.05 × their twin where the twin itself is above 1.10 × "
                + "the floor, 1 meet neither"), md);
        assertTrue(md.contains("over its geometry-only twin's (named and null scenarios): ≤ 1.05: 2, 1.05–1.10: 0, 1.10–1.15: 0, 1.15–1.5: 1"), md);
        // a run without a validation RMS beside one whose twin was diagnosed: no ratio to the twin, its column says so
        String row = DiagnosisBenchmark.row("y", List.of(run(Double.NaN, 1.14)));
        assertTrue(row.contains("| 1.14 | - | - |"), row);
    }

    @Test
    void row_takesItsValidationRatiosOverTheRunsThatHaveThem() {
        var noValidation = new DiagnosisBenchmark.Run("z", Expected.outside(), 1, DiagnosisBenchmark.Outcome.LOCATED_ONLY, List.of(),
                List.of("a smooth, non-periodic function of joint 2's angle"), Double.NaN, Double.NaN, Double.NaN, 10, 0, 0, 0);
        String row = DiagnosisBenchmark.row("all", List.of(run(1.02, Double.NaN), noValidation));
        assertTrue(row.contains("| 1.20 | 1.02 | 1.02 |"), row);
        String alone = DiagnosisBenchmark.row("z", List.of(noValidation));
        assertTrue(alone.contains("| - | - | - |") && !alone.contains("NaN"), alone);
    }

    @Test
    void table_listsNamedRightRunsWithAStructureLocatedBeside() {
        Expected lm = Expected.named(Expected.claim(Expected.Family.LOST_MOTION, 2));
        var plain = new DiagnosisBenchmark.Run("a", lm, 1, DiagnosisBenchmark.Outcome.NAMED_RIGHT, List.of("backlash j2"), List.of(), 5, 1.02,
                1.01, 10, 0, 0, 0);
        var beside = new DiagnosisBenchmark.Run("b", lm, 2, DiagnosisBenchmark.Outcome.NAMED_RIGHT, List.of("backlash j2"),
                List.of("joint 3's zero jumps at about 316 s"), 5, 1.03, 1.01, 10, 0, 0, 0);
        String md = DiagnosisBenchmark.markdown(List.of(plain, beside));
        assertTrue(md.contains("Named right, with a structure located beside that no named effect explains: 1 of 2 runs:\n"
                + "- b (seed 2): joint 3's zero jumps at about 316 s\n"), md);
    }

    static DiagnosisBenchmark.Run run(double finalRatio, double twinRatio) {
        return new DiagnosisBenchmark.Run("x", Expected.none(), 1, DiagnosisBenchmark.Outcome.CLEAN, List.of(), List.of(), 1.2, finalRatio,
                twinRatio, 10, 0, 0, 0);
    }

    @Test
    void scoringFollowsTheExpectedAnswer() {
        String lm2 = DiagnosisBenchmark.key(Expected.Family.LOST_MOTION, List.of(2));
        String lm1 = DiagnosisBenchmark.key(Expected.Family.LOST_MOTION, List.of(1));
        String th = DiagnosisBenchmark.key(Expected.Family.THERMAL_GROWTH, List.of());
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_RIGHT, DiagnosisBenchmark.score(Expected.Verdict.NAMED, Set.of(lm2), Set.of(lm2), false));
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_WRONG, DiagnosisBenchmark.score(Expected.Verdict.NAMED, Set.of(lm2), Set.of(lm1), false));
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_WRONG, DiagnosisBenchmark.score(Expected.Verdict.NAMED, Set.of(lm2), Set.of(lm2, th), false));
        assertEquals(DiagnosisBenchmark.Outcome.LOCATED_ONLY, DiagnosisBenchmark.score(Expected.Verdict.NAMED, Set.of(lm2, th), Set.of(th), false));
        assertEquals(DiagnosisBenchmark.Outcome.MISSED, DiagnosisBenchmark.score(Expected.Verdict.NAMED, Set.of(lm2), Set.of(), false));
        assertEquals(DiagnosisBenchmark.Outcome.LOCATED_ONLY, DiagnosisBenchmark.score(Expected.Verdict.OUTSIDE, Set.of(), Set.of(), true));
        assertEquals(DiagnosisBenchmark.Outcome.NAMED_WRONG, DiagnosisBenchmark.score(Expected.Verdict.OUTSIDE, Set.of(), Set.of(th), true));
        assertEquals(DiagnosisBenchmark.Outcome.MISSED, DiagnosisBenchmark.score(Expected.Verdict.OUTSIDE, Set.of(), Set.of(), false));
        assertEquals(DiagnosisBenchmark.Outcome.FALSE_CLAIM, DiagnosisBenchmark.score(Expected.Verdict.NULL, Set.of(), Set.of(), true));
        assertEquals(DiagnosisBenchmark.Outcome.CLEAN, DiagnosisBenchmark.score(Expected.Verdict.NULL, Set.of(), Set.of(), false));
        assertTrue(DiagnosisBenchmark.distribution(new double[] {1.0, 1.12, 3}).startsWith("≤ 1.05: 1, 1.05–1.10: 0, 1.10–1.15: 1"));
    }
}
