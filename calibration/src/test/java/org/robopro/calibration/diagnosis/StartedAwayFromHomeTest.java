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

    /** Seeds of the scenario whose first pose's true flank on joint 2 differs from (or agrees with) a move from zero. */
    private static List<Scenario.Trial> trials(boolean differs, int n) {
        List<Scenario.Trial> out = new java.util.ArrayList<>();
        for (long seed = 20261124; seed < 20261164 && out.size() < n; seed++) {
            Scenario.Trial t = Scenario.named(AWAY).trial(seed, p -> p);
            Campaign.Row first = t.campaign().rows().get(0);
            if ((first.q()[1] * first.dir()[1] < 0) == differs) out.add(t);
        }
        assertEquals(n, out.size(), "the world draws both kinds of start");
        return out;
    }

    @Test
    void firstPosesFlank_isTakenFromItsResidual_whenTheCampaignStartedElsewhere() {
        // before: a training pose 1 on the other flank was flagged as an outlier; a validation pose 1 left up to 1.47 x the floor
        for (Scenario.Trial t : trials(true, 3)) {
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            String id = t.campaign().rows().get(0).id();
            assertEquals(List.of("backlash j2"), d.effects().stream().map(f -> f.effect().label()).toList(), "seed " + t.seed());
            assertEquals(List.of(), d.outliers(), "seed " + t.seed() + ": no bad measurement in the campaign");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + t.seed() + ": " + d.finalValidateRmsM() / c.floorM() + " x floor");
            assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("pose " + id + "'s direction on joint 2 taken from its residual: the "
                    + "campaign seems to start away from the zero position")), "seed " + t.seed() + ": " + d.notes());
        }
    }

    @Test
    void firstPosesFlank_staysWhenItAgreesWithAMoveFromZero() {
        List<Scenario.Trial> ts = new java.util.ArrayList<>(trials(false, 1));
        Scenario.Trial home = Scenario.named("lost motion j2, directions not recorded").trial(20261124, p -> p);
        Campaign.Row first = home.campaign().rows().get(0);
        assertTrue(first.q()[1] * first.dir()[1] > 0, "from the home position: the flank of a move from zero");
        ts.add(home);
        for (Scenario.Trial t : ts) {
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            assertEquals(List.of("backlash j2"), d.effects().stream().map(f -> f.effect().label()).toList(), t.scenario().name());
            assertTrue(d.notes().stream().noneMatch(n -> n.contains("start away from the zero position")), t.scenario().name() + ": " + d.notes());
        }
    }
}
