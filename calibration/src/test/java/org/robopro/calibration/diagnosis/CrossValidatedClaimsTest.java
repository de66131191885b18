package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
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

    private static List<String> families(Diagnosis d) {
        return d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
    }

    /**
     * A 6-D campaign whose only structure is an error of joint 2 depending on joints 2 and 4 (no
     * family's): on the training poses alone a 20-cycle harmonic of joint 6 passes the tests, but
     * the folds do not find it again, so it is not named.
     */
    @Test
    void aHarmonicTheFoldsDoNotFindAgain_isNotNamed() {
        WorldCampaigns.Sim c = world("outside: j2 error depending on j2 and j4, 6-D", 20261126);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), null);
        assertEquals(List.of(), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("gear-periodic j6 is not claimed: only")), d.notes().toString());
        assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joints 2 and 4")), d.located().toString());
    }

    /** Real lost motion is named by the folds too, and their held-out error says how much it helps. */
    @Test
    void anEffectTheFoldsFindAgain_staysNamed() {
        WorldCampaigns.Sim c = world("lost motion j2, directions recorded", 7);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), null);
        assertEquals(List.of("backlash j2"), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("no validation poses: the claims were judged by 5-fold")),
                d.notes().toString());
    }

    /** Too few poses for the folds: the report says the claims rest on the leave-one-pose-out error only. */
    @Test
    void tooFewPosesForTheFolds_saysSo() {
        WorldCampaigns.Sim c = world("lost motion j2, directions recorded", 7);
        var small = c.train().withRows(c.train().rows().subList(0, 45));
        Diagnosis d = Diagnoser.diagnose(irb2000, small, null);
        assertEquals(List.of("backlash j2"), families(d), "notes " + d.notes());
        assertTrue(d.notes().stream().anyMatch(n -> n.contains("not by 5-fold cross-validation")), d.notes().toString());
    }
}
