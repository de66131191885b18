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
 * Structures outside every physical family, drawn by the independent world simulator
 * (org.robopro.world: its own kinematics and its own error forms, nothing shared with
 * {@link Effect}), must be located with their variables and never named as a family. Where the
 * located structure's fallback holds on held-out poses it may model it, as a structure of no
 * known family; clean poses are not reported as outliers because of it.
 */
class OutsideFamiliesTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    private static WorldCampaigns.Sim world(String scenario, long seed) {
        return WorldCampaigns.of(Scenario.named(scenario).trial(seed, p -> p));
    }

    /** No physical family named: every effect is a fallback. */
    private static void namesNoFamily(Diagnosis d) {
        List<String> families = d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
        assertEquals(List.of(), families, "named a family for a structure outside every family; notes " + d.notes());
    }

    private static boolean locatedIn(Diagnosis d, String variable) {
        return d.located().stream().anyMatch(l -> l.variable().equals(variable));
    }

    @Test
    void errorOfJoint2DependingOnJoints2And4_isLocatedInBothJointsAndNotNamed() {
        WorldCampaigns.Sim c = world("outside: j2 error depending on j2 and j4", 3);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        namesNoFamily(d);
        assertTrue(locatedIn(d, "joints 2 and 4"), d.located().toString());
        // The two-joint fallback holds on the validation poses: it brings them near the noise floor.
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == Effect.Kind.PAIR), d.effects().toString());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
        assertTrue(d.geometricValidateRmsM() > 1.5 * c.floorM(), "the structure matters: " + d.geometricValidateRmsM());
    }

    /**
     * A structure located with no family selected beside it (none to withdraw, so no claim check
     * puts a fallback in its place) is modelled by its fallback all the same: the measured target
     * knocked on the flange (its step at a time), the measured point sagging with its reach (its
     * displacement along reach). Each was located and left at its size (4.1 and 1.7 x the floor).
     */
    @Test
    void structureLocatedWithNothingBeside_isModelledByItsFallback() {
        Object[][] cases = {{"outside: measured target knocked mid-campaign", 20261126L, Effect.Kind.TARGET_STEP, 0.4},
                {"outside: measured point sags with reach, 50 poses", 20261124L, Effect.Kind.POINT_SMOOTH, 0.85}};
        for (Object[] k : cases) {
            WorldCampaigns.Sim c = world((String) k[0], (Long) k[1]);
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            namesNoFamily(d);
            assertTrue(d.effects().stream().anyMatch(f -> f.effect().kind() == k[2]), k[0] + ": " + d.effects());
            // and the fallback holds on the validation poses: well below the geometry's error there
            assertTrue(d.finalValidateRmsM() < (Double) k[3] * d.geometricValidateRmsM(), k[0] + ": " + d.finalValidateRmsM() / c.floorM() + " x floor, geometry alone "
                    + d.geometricValidateRmsM() / c.floorM());
        }
    }

    @Test
    void pointSaggingWithReach_isLocatedInReachAndNotNamed() {
        WorldCampaigns.Sim c = world("outside: measured point sags with reach", 4);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        namesNoFamily(d);
        assertTrue(locatedIn(d, "reach of the measured point"), d.located().toString());
    }

    @Test
    void bumpInJoint3_isLocatedNotNamedAndFlagsNoCleanPose() {
        WorldCampaigns.Sim c = world("outside: bump in the angle of j3", 1);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        namesNoFamily(d);
        assertTrue(locatedIn(d, "joint 3 angle"), d.located().toString());
        assertEquals(List.of(), d.outliers(), "the campaign has no bad measurement");
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    @Test
    void encoderSlipMidCampaign_isLocatedAsAJumpOfJoint2sZeroAndFlagsNoCleanPose() {
        WorldCampaigns.Sim c = world("outside: encoder slip on j2 mid-campaign", 2);
        Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
        namesNoFamily(d);
        assertTrue(d.located().stream().anyMatch(l -> l.shape().startsWith("joint 2's zero jumps")), d.located().toString());
        assertEquals(List.of(), d.outliers(), "the campaign has no bad measurement");
    }

    /**
     * Drawn campaigns on which a family was once named beside the located structure's fallback: the
     * fallback took the structure and left the family a share of the noise that lowered the
     * leave-one-pose-out error by a hair (zero creep named instrument drift, bending under payload
     * named compliance of joint 5), or a wrist harmonic fitted to the training noise raised the
     * 6-D validation error. None of them may be named.
     */
    @Test
    void structuresOnceNamedBesideTheirFallback_areLocatedAndNotNamed() {
        record Case(String scenario, long seed, String variable) { }
        for (Case k : List.of(new Case("outside: j3 zero creeping with time", 7, "time"),
                new Case("outside: arm bends with payload and reach", 7, "payload and reach"),
                new Case("outside: j2 error depending on j2 and j4, 6-D", 20261126, "joints 2 and 4"))) {
            WorldCampaigns.Sim c = world(k.scenario(), k.seed());
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            namesNoFamily(d);
            assertTrue(d.located().stream().anyMatch(l -> l.variable().contains(k.variable())), k + ": " + d.located());
        }
    }
}
