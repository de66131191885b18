package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Scenario;

/**
 * Without validation poses the claims are judged by K-fold cross-validation of the whole diagnosis.
 * The campaigns come from the independent world simulator (org.robopro.world), read back as text.
 */
class CrossValidatedClaimsTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    /** The world trial of a seed, its campaign drawn from the plan seeded with that seed (the campaigns these claims were checked on). */
    private static WorldCampaigns.Sim world(String scenario, long seed) {
        return WorldCampaigns.of(Scenario.named(scenario).trial(seed, p -> p.withSeed(seed)));
    }

    /** The lost-motion campaign of seed 7, without its validation poses, and its diagnosis (the K-fold path): made once, read by several tests. */
    private static WorldCampaigns.Sim lostMotion;
    private static Diagnosis lostMotionDiagnosis;

    private static synchronized WorldCampaigns.Sim lostMotion() {
        if (lostMotion == null) lostMotion = world("lost motion j2, directions recorded", 7);
        return lostMotion;
    }

    private static synchronized Diagnosis lostMotionDiagnosed() {
        if (lostMotionDiagnosis == null) lostMotionDiagnosis = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), lostMotion().train(), null);
        return lostMotionDiagnosis;
    }

    private static List<String> families(Diagnosis d) {
        return d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
    }

    /**
     * A 6-D campaign whose only structure is an error of joint 2 depending on joints 2 and 4 (no
     * family's), diagnosed by the folds: nothing is named and the structure is located. (Weighted
     * by the geometric fit's σ of the rotations, a 20-cycle harmonic of joint 6 passed the tests on
     * the training poses and only the folds stopped it; weighted by the noise the model leaves, it
     * does not pass. The folds' own judgement of a chance family is held by
     * {@link #eachFamily_isJudgedOnItsOwnByTheFolds}.)
     */
    @Test
    void aStructureOfNoFamilyIn6D_isLocatedAndNotNamedByTheFolds() {
        WorldCampaigns.Sim c = world("outside: j2 error depending on j2 and j4, 6-D", 20261126);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), null);
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().noneMatch(n -> n.startsWith("gear-periodic j6")), d.notes().toString());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joints 2 and 4")), d.located().toString());
    }

    /** Real lost motion is named by the folds too, and their held-out error says how much it helps. */
    @Test
    void anEffectTheFoldsFindAgain_staysNamed() {
        Diagnosis d = lostMotionDiagnosed();
        assertEquals(List.of("backlash j2"), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("no validation poses: the claims were judged by 5-fold")),
                d.notes().toString());
    }

    /**
     * Each named family is judged by the folds on its own: a real lost motion (the world's truth)
     * beside a chance-level family put into the final model (a gear harmonic set of joint 4 fitted
     * to noise; the world has no error on joint 4). Pooled, the two lower the held-out error
     * together; on its own, dropping the chance family does not raise the folds' held-out error,
     * while dropping the lost motion does.
     */
    @Test
    void eachFamily_isJudgedOnItsOwnByTheFolds() {
        MeasurementSet train = lostMotion().train();
        Diagnosis d = lostMotionDiagnosed();
        assertEquals(List.of("backlash j2"), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("backlash j2: named by 5 of 5 folds; the folds' held-out error")),
                d.notes().toString());
        Effect chance = Effect.periodic(3, new int[] {11, 12, 13, 14, 15, 16, 17, 18, 19, 20});
        Diagnosis.Finding real = d.effects().get(0);
        List<Diagnosis.Finding> both = List.of(real, new Diagnosis.Finding(chance, new double[chance.size()], new double[chance.size()],
                Double.NaN, Double.NaN, real.evidence(), null, ""));
        Diagnosis withChance = new Diagnosis(d.robot(), d.geometric(), d.sigmaM(), d.geometricTrainRmsM(), d.geometricValidateRmsM(),
                both, d.finalTrainRmsM(), d.finalValidateRmsM(), d.outliers(), d.notIdentifiable(), d.implausible(), d.recommendations(),
                d.notes(), d.model(), d.finalFlangeTtool(), d.finalInstrumentTbase(), d.candidatesTested(), d.alpha(), d.elapsedMs(),
                d.directions(), d.located(), d.warnings());
        int k = 5, n = train.size();
        int[] fold = MeasurementSet.folds(n, k, n);
        List<Diagnoser.Fold> folds = new ArrayList<>();
        for (int f = 0; f < k; f++) {
            List<Measurement> tr = new ArrayList<>(), va = new ArrayList<>();
            for (int i = 0; i < n; i++) (fold[i] == f ? va : tr).add(train.rows().get(i));
            folds.add(Diagnoser.Fold.of(Diagnoser.diagnose(irb2000, train.withRows(tr), train.withRows(va))));
        }
        Map<String, double[]> held = Diagnoser.perFamilyHeldOut(irb2000, train, fold, folds, withChance, Diagnoser.Options.defaults());
        double[] lost = held.get("backlash j2"), gear = held.get("gear-periodic j4");
        assertTrue(lost[0] < 0.5 * lost[1], "the lost motion predicts the held-out poses: " + Arrays.toString(lost));
        assertTrue(gear[0] >= gear[1], "the chance family does not: " + Arrays.toString(gear));
    }

    /** Too few poses for the folds: the report says the claims rest on the leave-one-pose-out error only. */
    @Test
    void tooFewPosesForTheFolds_saysSo() {
        var small = lostMotion().train().withRows(lostMotion().train().rows().subList(0, 45));
        Diagnosis d = Diagnoser.diagnose(irb2000, small, null);
        assertEquals(List.of("backlash j2"), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.contains("not by 5-fold cross-validation")), d.notes().toString());
    }

    /**
     * A family is claimed only when every fold but at most one names it (and a majority): with five
     * folds, 4 of 5, not 3 of 5, which a soft foot and a motor resolver reached on clean-room sets
     * and were named wrongly for.
     */
    @Test
    void foldsAgree_everyFoldButOne() {
        assertTrue(Diagnoser.foldsAgree(5, 5));
        assertTrue(Diagnoser.foldsAgree(4, 5));
        assertFalse(Diagnoser.foldsAgree(3, 5));
        assertTrue(Diagnoser.foldsAgree(2, 3));
        assertFalse(Diagnoser.foldsAgree(1, 3));
        assertTrue(Diagnoser.foldsAgree(2, 2));
        assertFalse(Diagnoser.foldsAgree(1, 2));
        assertTrue(Diagnoser.foldsAgree(9, 10));
        assertFalse(Diagnoser.foldsAgree(8, 10));
    }

    /** The arm's growth counts the same in a fold uniform or link by link; other families by their own key. */
    @Test
    void foldCount_growthInEitherForm() {
        java.util.Map<String, Integer> c = java.util.Map.of("thermal-link", 2, "thermal-expansion", 3, "backlash j2", 3, "instrument-drift", 1);
        assertEquals(5, Diagnoser.foldCount(c, "thermal-link", 5));
        assertEquals(5, Diagnoser.foldCount(c, "thermal-expansion", 5));
        assertEquals(3, Diagnoser.foldCount(c, "backlash j2", 5));
        assertEquals(1, Diagnoser.foldCount(c, "instrument-drift", 5));
        assertEquals(0, Diagnoser.foldCount(c, "backlash j1", 5));
    }
}
