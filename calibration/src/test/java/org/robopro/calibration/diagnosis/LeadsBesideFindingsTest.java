package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * A located structure is a claim the user reads ("joint 3's zero jumps at about 316 s"): beside a
 * correctly named effect it must be one the data hold, not what the geometric fit leaves of that
 * effect. The truth is the independent world simulator's (org.robopro.world: its own kinematics,
 * each link growing by its own coefficient with the true temperature, an aluminium target holder;
 * nothing shared with {@link Effect}). What the geometric fit leaves of the warm-up has a step in
 * time among its nearest shapes; once the thermal growth is fitted the step is gone, and it must
 * not be reported as a structure no named effect explains. A real step (an encoder slipping
 * mid-campaign, which nothing thermal makes) beside the same growth is still located.
 */
class LeadsBesideFindingsTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    /** Located structures that no named effect explains: what a user would read as a finding beside the named ones. */
    private static List<String> unexplained(Diagnosis d) {
        List<String> out = new ArrayList<>();
        for (Diagnosis.Located l : d.located()) if (l.explainedBy() == null) out.add(l.stage() + ": " + l.shape());
        return out;
    }

    private static boolean namesThermal(Diagnosis d) {
        return d.effects().stream().anyMatch(f -> switch (f.effect().kind()) {
            case THERMAL, THERMAL_LINK, DRIFT -> true;
            default -> false;
        });
    }

    /** Only thermal families named: no fallback, no other family. */
    private static void namesThermalOnly(Diagnosis d) {
        assertTrue(namesThermal(d), "thermal growth not named: " + d.effects());
        for (Diagnosis.Finding f : d.effects())
            assertTrue(f.effect().kind() == Effect.Kind.THERMAL || f.effect().kind() == Effect.Kind.THERMAL_LINK
                    || f.effect().kind() == Effect.Kind.DRIFT, "named beside the growth: " + f.effect().label());
    }

    @Test
    void thermalGrowthPerLink_reportsNoStepInTimeBesideIt() {
        // Seeds on which a zero step of joint 3 (about 316 s) and a move of the target on the flange (about 1671 s)
        // were reported beside the named growth, as structures no named effect explains.
        for (long seed : new long[] {20261125L, 20261126L}) {
            WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named("thermal growth per link").trial(seed));
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            namesThermalOnly(d);
            assertEquals(List.of(), unexplained(d), "seed " + seed + ": a lead beside the growth; located " + d.located());
            // The steps the geometric fit's residuals showed are said to be the growth's.
            for (Diagnosis.Located l : d.located())
                if (l.shape().contains("jumps at") || l.shape().contains("moved on the flange"))
                    assertTrue(l.words().contains("explained by") && l.words().contains("not a structure of its own"), l.words());
            assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
        }
    }

    @Test
    void encoderSlipBesideThermalGrowth_isStillLocated() {
        // The same growth as above (seed 20261125) with joint 2's encoder slipping by 0.01 deg at 1500 s.
        Scenario.Trial t = Scenario.named("thermal growth per link").trial(20261125L);
        List<JointError> errors = new ArrayList<>(t.world().errors());
        errors.add(new JointError.Slip(1, 1500, Math.toRadians(0.01)));
        WorldRobot slipping = t.world().withErrors(errors);
        WorldCampaigns.Sim c = WorldCampaigns.measure(irb2000, slipping, t.campaign().plan());
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(namesThermal(d), "thermal growth not named: " + d.effects().stream().map(f -> f.effect().label()).toList()
                + ", located " + unexplained(d) + ", notes " + d.notes());
        boolean stepModelled = d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.ZERO_STEP && f.effect().joint() == 1);
        List<Diagnosis.Located> steps = d.located().stream()
                .filter(l -> l.explainedBy() == null && l.shape().startsWith("joint 2's zero jumps at about ")).toList();
        assertTrue(stepModelled || !steps.isEmpty(), "the slip is neither located nor modelled: located " + unexplained(d) + ", effects "
                + d.effects().stream().map(f -> f.effect().label()).toList());
        for (Diagnosis.Located l : steps) {
            double at = Double.parseDouble(l.shape().replaceAll("[^0-9.]+", " ").trim().split(" ")[1]);
            assertTrue(Math.abs(at - 1500) < 150, "the slip was at 1500 s: " + l.shape());
        }
        // No family is named for the slip.
        for (Diagnosis.Finding f : d.effects())
            assertTrue(f.effect().isFallback() || namesThermal(d) && (f.effect().kind() == Effect.Kind.THERMAL
                    || f.effect().kind() == Effect.Kind.THERMAL_LINK || f.effect().kind() == Effect.Kind.DRIFT), "named: " + f.effect().label());
    }

    @Test
    void harmonicLeftBesideWindUpThatValidationDoesNotConfirm_isAWeakLeadNotALocatedStructure() {
        // A lost motion that builds up over the move, every pose approached by a move the file does not hold, and no dir
        // columns: the directions inferred from the measuring order miss the approaches, and what the model leaves looks like
        // a harmonic of joint 3 on the training poses (38 cycles per turn of its angle, or 6 of its link angle); fitted, it does
        // not lower the validation error.
        WorldCampaigns.Sim c = WorldCampaigns.of(Scenario.named(
                "lost motion j3 building up over the move, approached by 0.5-10 deg from above, a fifth from below")
                .trial(20261131L, p -> p.withDirColumns(false)));
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.BACKLASH && f.effect().joint() == 2),
                "lost motion of joint 3 not named: " + d.effects());
        // (a harmonic of joint 3's own angle or of its link angle, whichever the residual shows more of)
        assertTrue(d.located().stream().noneMatch(l -> l.explainedBy() == null && l.shape().contains("cycles per turn")
                && l.shape().contains("joint 3")), "an unconfirmed harmonic reported as located: " + unexplained(d));
        assertTrue(d.notes().stream().anyMatch(n -> n.startsWith("A weak lead, not a finding") && n.contains("cycles per turn")
                && n.contains("joint 3") && n.contains("does not lower the validation")), "no weak lead in the notes: " + d.notes());
    }
}
