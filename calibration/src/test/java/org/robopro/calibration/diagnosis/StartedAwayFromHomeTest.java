package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Campaign;
import org.robopro.world.Scenario;

/**
 * A campaign without dir columns that started where the previous program left the robot (the
 * independent world's truth: each drive last moved either way), not at the zero position the
 * inference assumes. The first pose's flank on the joint with lost motion is then taken from its
 * residual: it is not flagged as an outlier, a validation pose does not miss by the play, and the
 * notes say so. Where the world's first flank agrees with a move from zero, nothing changes.
 */
class StartedAwayFromHomeTest {
    private static final String AWAY = "lost motion j2, directions not recorded, started away from home";
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    @Test
    void firstPosesFlank_isTakenFromItsResidual_whenTheCampaignStartedElsewhere() {
        // 20261124: pose 1 is a training pose (it was flagged as an outlier); 20261125: a validation pose (1.47 x the floor)
        for (long seed : new long[] {20261124, 20261125}) {
            Scenario.Trial t = Scenario.named(AWAY).trial(seed, p -> p);
            Campaign.Row first = t.campaign().rows().get(0);
            assertTrue(first.q()[1] * first.dir()[1] < 0, "the world started elsewhere: a move from zero gives the other flank");
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            assertEquals(List.of("backlash j2"), d.effects().stream().map(f -> f.effect().label()).toList(), "seed " + seed);
            assertEquals(List.of(), d.outliers(), "seed " + seed + ": no bad measurement in the campaign");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM() + " x floor");
            assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("pose 1's direction on joint 2 taken from its residual: the "
                    + "campaign seems to start away from the zero position")), "seed " + seed + ": " + d.notes());
        }
    }

    @Test
    void firstPosesFlank_staysWhenItAgreesWithAMoveFromZero() {
        for (String s : List.of(AWAY, "lost motion j2, directions not recorded")) {
            long seed = s.equals(AWAY) ? 20261126 : 20261124;
            Scenario.Trial t = Scenario.named(s).trial(seed, p -> p);
            Campaign.Row first = t.campaign().rows().get(0);
            assertTrue(first.q()[1] * first.dir()[1] > 0, "the world's first flank is that of a move from zero");
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            assertEquals(List.of("backlash j2"), d.effects().stream().map(f -> f.effect().label()).toList(), s);
            assertTrue(d.notes().stream().noneMatch(n -> n.contains("start away from the zero position")), s + ": " + d.notes());
        }
    }
}
