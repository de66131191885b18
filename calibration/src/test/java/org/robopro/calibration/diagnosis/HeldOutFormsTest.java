package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Campaign;
import org.robopro.world.Expected;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * Forms an independent held-out simulator concealed and the diagnosis once named as the wrong
 * physics, drawn here by the world simulator (org.robopro.world: its own kinematics and error
 * forms, nothing shared with {@link Effect}): each must be located and not named as a family,
 * while the family it was taken for is still named where it is the truth.
 */
class HeldOutFormsTest {

    /** A world scenario on a shipped robot with the given drive errors, measured with the default plan adjusted. */
    static WorldCampaigns.Sim world(String robot, Expected expected, List<JointError> errors, UnaryOperator<Campaign.Plan> plan, long seed) {
        Scenario s = new Scenario("held-out form", "outside", robot, expected, (n, r) -> w -> {
            List<JointError> all = new ArrayList<>(w.errors());
            all.addAll(errors);
            return w.withErrors(all);
        }, plan);
        return WorldCampaigns.of(s.trial(seed));
    }

    static List<String> families(Diagnosis d) {
        return d.effects().stream().filter(f -> !f.effect().isFallback()).map(f -> f.effect().label()).toList();
    }

    /**
     * Joint 3's error following the product of joints 2 and 3 on the IRB 2400's parallel arm: its
     * part linear in q2 looks like a coupling of joint 3 from joint 2, and a coupling was named
     * beside the two-joint fallback that held the rest. The fallback holds the linear terms of both
     * joints, so the coupling is nested in it and not named.
     */
    @Test
    void errorOfJoint3FromTheProductOfJoints2And3_isNotNamedACoupling() {
        for (long seed : new long[] {3, 11}) {
            WorldCampaigns.Sim c = world("irb2400", Expected.outside(),
                    List.of(new JointError.AngleProduct(2, 1, 2, Math.toRadians(0.04))), p -> p, seed);
            Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
            assertEquals(List.of(), families(d), "seed " + seed + ": notes " + d.notes());
            assertTrue(d.located().stream().anyMatch(l -> l.variable().equals("joints 3 and 2")), d.located().toString());
            assertTrue(d.geometricValidateRmsM() > 1.5 * c.floorM(), "the structure matters: " + d.geometricValidateRmsM());
        }
    }

    /** A true coupling of joint 3 from joint 2 on the same arm is still named (the nested fallback does not take it). */
    @Test
    void couplingOfJoint3FromJoint2_isStillNamed() {
        WorldCampaigns.Sim c = world("irb2400", Expected.outside(),
                List.of(new JointError.Coupling(2, 1, 8e-4)), p -> p, 5);
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(List.of("joint-coupling j3<-j2"), families(d), "notes " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }
}
