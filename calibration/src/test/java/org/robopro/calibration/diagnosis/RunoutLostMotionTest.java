package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.JointError;
import org.robopro.world.Scenario;

/**
 * Lost motion whose play changes over the turn of its joint, against the independent world's
 * truth: an output gear that runs off its bearing's centre, the play changing with the centre
 * distance by 2·Δa·tan α (the world's own gear geometry, nothing shared with {@link Effect}).
 * Named on its joint with the play's mean, change and widest angle near the truth's, at the
 * floor; a constant play named constant is in {@link WindUpLostMotionTest}.
 */
class RunoutLostMotionTest {
    private final RobotDescription irb2000 = RobotLibrary.shipped("irb2000");

    @Test
    void playChangingOverTheTurn_namedOnJoint2_withTheTruthsPlay_atTheFloor() {
        Scenario s = Scenario.named("lost motion j2 whose play changes over the turn (output gear runout)");
        for (long seed : new long[] {20261124, 20261126}) {
            Scenario.Trial t = s.trial(seed);
            WorldCampaigns.Sim c = WorldCampaigns.of(t);
            JointError.RunoutLostMotion truth = t.world().errors().stream().filter(e -> e instanceof JointError.RunoutLostMotion)
                    .map(e -> (JointError.RunoutLostMotion) e).findFirst().orElseThrow();
            Diagnosis d = Diagnoser.diagnose(irb2000, c.train(), c.validation());
            assertEquals(1, d.effects().size(), "seed " + seed + ": " + d.effects() + " " + d.notes());
            Diagnosis.Finding f = d.effects().get(0);
            assertEquals(Effect.Kind.BACKLASH, f.effect().kind());
            assertEquals(1, f.effect().joint());
            assertTrue(f.effect().runout(), "seed " + seed + ": " + f.effect().label());
            double[] v = f.values();
            // the truth's play over the turn: width + A cos(q - phase), A = 2 e tan(alpha) / r
            double change = 2 * truth.runoutM() * Math.tan(truth.pressureAngle()) / truth.pitchRadiusM();
            assertEquals(truth.width(), v[0], 0.1 * truth.width(), "seed " + seed + ": mean play");
            assertEquals(change, Math.hypot(v[1], v[2]), 0.2 * change, "seed " + seed + ": change over the turn");
            double widest = Math.atan2(v[2], v[1]);
            assertEquals(0, Math.IEEEremainder(widest - truth.phase(), 2 * Math.PI), Math.toRadians(15), "seed " + seed + ": widest angle");
            assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), "seed " + seed + ": " + d.finalValidateRmsM() / c.floorM());
        }
    }

    @Test
    void playChangingOverTheTurn_directionsFromTheMeasuringOrder() {
        Scenario s = Scenario.named("lost motion j1 irb2400 whose play changes over the turn (output gear runout), directions not recorded");
        WorldCampaigns.Sim c = WorldCampaigns.of(s.trial(20261125));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2400"), c.train(), c.validation());
        assertEquals(1, d.effects().size(), d.effects() + " " + d.notes());
        Effect e = d.effects().get(0).effect();
        assertEquals(0, e.joint());
        assertTrue(e.runout(), e.label());
        assertTrue(d.finalValidateRmsM() <= 1.15 * c.floorM(), d.finalValidateRmsM() / c.floorM() + " x floor");
    }

    /**
     * The regressor by hand: the output lags by half the play, b(q) = b + b_cos cos q + b_sin sin q,
     * behind the direction it last moved in; the robot file keeps the form.
     */
    @Test
    void regressorAndRobotFile() {
        Effect e = Effect.withRunout(Effect.backlash(1));
        assertEquals(3, e.size());
        double q2 = Math.toRadians(60);
        double[] g = new double[3];
        e.regressor(new double[] {0, q2, 0, 0, 0, 0}, new PoseConditions(new int[] {0, -1, 0, 0, 0, 0}, 0, Double.NaN, Double.NaN), g);
        assertArrayEquals(new double[] {0.5, 0.5 * Math.cos(q2), 0.5 * Math.sin(q2)}, g, 1e-15, "moved down: the output sits half the play above");
        KinematicModel model = KinematicModel.build(irb2000);
        double[] v = {7e-4, 1e-4, -2e-4};
        Effect.Term back = Effect.fromDescription(e.describe(v), model, null, "x.json");
        assertTrue(back.effect().runout());
        assertArrayEquals(v, back.values(), 0);
        assertEquals(Effect.Kind.BACKLASH, Effect.withoutRunout(back.effect()).kind());
        assertTrue(!Effect.withoutRunout(back.effect()).runout());
    }
}
