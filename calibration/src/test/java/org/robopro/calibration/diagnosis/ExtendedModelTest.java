package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.simulation.TrueRobot;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;

class ExtendedModelTest {
    private final RobotDescription robot = RobotLibrary.shipped("irb2000");
    private final KinematicModel model = KinematicModel.build(robot);
    private final GravityTorques g = new GravityTorques(model, robot.massModel().orElseThrow());
    private final List<Effect.Term> terms = List.of(
            new Effect.Term(Effect.compliance(1, g), new double[] {1e-6}),
            new Effect.Term(Effect.backlash(1), new double[] {8e-4}),
            new Effect.Term(Effect.thermal(20), new double[] {20e-6}),
            new Effect.Term(Effect.coupling(2, 1), new double[] {5e-4}));
    private final PoseConditions c = new PoseConditions(new int[] {1, -1, 1, 1, -1, 1}, 300, 31, 7);
    private final Pose tool = Pose.translation(0, 0, 0.1);

    private TrueRobot truth() {
        List<JointEffect> es = new ArrayList<>();
        for (Effect.Term t : terms) es.add(t.effect().truth(t.values()));
        return new TrueRobot(model, tool, Pose.IDENTITY, 0, 0, es);
    }

    @Test
    void tool_sameEffectsAsSimulatedTruth_samePose() {
        ExtendedModel ext = new ExtendedModel(model, terms);
        TrueRobot t = truth();
        for (double[] q : model.randomConfigurations(20, 4)) {
            Pose a = ext.tool(q, tool, c), b = t.tool(q, c);
            assertEquals(0, a.distanceTo(b), 1e-12);
            assertEquals(0, a.angleTo(b), 1e-12);
        }
    }

    @Test
    void robotFile_roundTrip_predictsTheSame() {
        ExtendedModel ext = new ExtendedModel(model, terms);
        String text = RobotFile.format(ext.toDescription());
        assertTrue(text.contains("\"effects\""), text);
        ExtendedModel back = ExtendedModel.of(RobotFile.parse("extended.robot.json", text), "extended.robot.json");
        assertEquals(terms.size(), back.terms().size());
        for (double[] q : model.randomConfigurations(10, 8))
            assertEquals(0, ext.tool(q, tool, c).distanceTo(back.tool(q, tool, c)), 1e-9);
    }

    @Test
    void compensator_extendedModel_trueRobotLandsOnTarget() {
        ExtendedModel ext = new ExtendedModel(model, terms);
        Compensator withEffects = new Compensator(model, ext, tool, tool, c);
        Compensator geometryOnly = new Compensator(model, model, tool, tool);
        TrueRobot t = truth();
        double worstWith = 0, worstWithout = 0;
        for (double[] q0 : model.randomConfigurations(10, 21)) {
            if (!new org.robopro.calibration.simulation.PoseSampler(model).acceptable(q0)) continue;
            Pose target = model.tool(q0, tool);
            Compensator.Result r = withEffects.compensate(target, q0);
            assertEquals(Compensator.Status.CONVERGED, r.status());
            worstWith = Math.max(worstWith, t.tool(r.q(), c).distanceTo(target));
            Compensator.Result r0 = geometryOnly.compensate(target, q0);
            worstWithout = Math.max(worstWithout, t.tool(r0.q(), c).distanceTo(target));
        }
        assertTrue(worstWith < 1e-7, "with effects the robot misses by " + worstWith);
        assertTrue(worstWithout > 1e-4, "the effects should matter: " + worstWithout);
    }

    /**
     * To reach a target the command must lead the lagging output: with backlash b on joint 2 and
     * approach direction dir, the compensated controller value of drive 2 is the target's plus
     * (b/2)·dir, every other drive unchanged (computed here by hand, not with the effect's code).
     */
    @Test
    void compensator_backlash_commandLeadsByHalfThePlay() {
        double b = Math.toRadians(0.05);
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(Effect.backlash(1), new double[] {b})));
        for (int dir : new int[] {1, -1}) {
            PoseConditions cond = new PoseConditions(new int[] {dir, dir, dir, dir, dir, dir}, 0, 20, 0);
            Compensator comp = new Compensator(model, ext, tool, tool, cond);
            double[] q0 = {0.3, 0.2, -0.1, 0.4, 0.5, 0.6};
            Pose target = model.tool(q0, tool);
            Compensator.Result r = comp.compensate(target, q0);
            assertEquals(Compensator.Status.CONVERGED, r.status());
            double[] q = r.q();
            assertEquals(b / 2 * dir, q[1] - q0[1], 1e-9, "drive 2 leads by half the play, dir " + dir);
            for (int j : new int[] {0, 2, 3, 4, 5}) assertEquals(q0[j], q[j], 1e-9, "drive " + (j + 1));
        }
    }
}
