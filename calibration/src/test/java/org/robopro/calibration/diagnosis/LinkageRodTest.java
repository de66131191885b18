package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotFile;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Scenario;

/**
 * A parallel arm whose rod is off its length: the world turns the forearm by the four-bar's
 * closure, a function of the forearm's angle to the upper arm θ3 = q3 − q2 alone, outside every
 * family. The diagnosis must locate it as one curve of that angle, name nothing, and report no
 * clean pose as a bad reading.
 */
class LinkageRodTest {

    @ParameterizedTest(name = "{0}, seed {1}")
    @CsvSource({"irb2400, 20261125", "irb2000, 20261126"})
    void locatedAsACurveOfTheForearmsAngle_namedAsNothing(String robot, long seed) {
        WorldCampaigns.Sim s = WorldCampaigns.of(Scenario.named("outside: parallel-arm rod off its length, " + robot).trial(seed, p -> p));
        Diagnosis d = Diagnoser.diagnose(s.nominal(), s.train(), s.validation());
        assertTrue(d.effects().stream().allMatch(f -> f.effect().isFallback()), "nothing named: " + d.effects());
        // one shape of θ3 alone: its curve, or its harmonics (the link angle's)
        Diagnosis.Finding curve = d.effects().stream().filter(f -> f.effect().label().startsWith("joint-smooth-error j3 (following theta3)")
                        || f.effect().label().startsWith("link-angle-periodic j3 (−q2 + q3"))
                .findFirst().orElseThrow(() -> new AssertionError("not located on θ3: " + d.effects()));
        assertTrue(curve.words().contains("four-bar") || curve.words().contains("rod"), curve.words());
        assertEquals(List.of(), d.outliers());
        assertTrue(d.finalValidateRmsM() < 1.10 * d.noiseFloorM(), d.finalValidateRmsM() / d.noiseFloorM() + " x the floor");
    }

    /** A link angle's harmonics, written to a robot file and read back, are the same error (its angle's coefficients kept). */
    @Test
    void robotFile_roundTrip_keepsTheLinkAngle() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2400"));
        double[] angle = Effect.linkAngle(model, 2);
        org.junit.jupiter.api.Assertions.assertArrayEquals(new double[] {0, -1, 1, 0, 0, 0}, angle, 1e-12, "q3 − q2 on the parallel arm");
        Effect e = Effect.linkPeriodic(2, angle, new int[] {5, 1});
        double[] v = {1e-4, -2e-4, 3e-5, 5e-5};
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(e, v)));
        ExtendedModel back = ExtendedModel.of(RobotFile.parse("x.robot.json", RobotFile.format(ext.toDescription())), "x.robot.json");
        assertEquals("link-angle-periodic j3 (−q2 + q3, h 1,5)", back.terms().get(0).effect().label());
        PoseConditions c = PoseConditions.NONE;
        for (double[] q : model.randomConfigurations(10, 9))
            assertEquals(0, ext.tool(q, Pose.IDENTITY, c).distanceTo(back.tool(q, Pose.IDENTITY, c)), 1e-12);
        // on the PUMA 560 (a serial arm) the forearm's angle to the ground
        org.junit.jupiter.api.Assertions.assertArrayEquals(new double[] {0, 1, 1, 0, 0, 0},
                Effect.linkAngle(KinematicModel.build(RobotLibrary.shipped("puma560")), 2), 1e-12);
    }

    /** The curve of drive 3's own arm angle, written to a robot file and read back, is the same curve (joints [3], model_angle). */
    @Test
    void robotFile_roundTrip_keepsTheArmAngle() {
        KinematicModel model = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        double[] v = {1e-4, -2e-4, 3e-4, 0, -1e-4, 2e-4, 1e-4, -3e-4};
        Effect e = Effect.smoothFollowingModelAngle(2, 2, model, -1.0, 1.0, v.length);
        ExtendedModel ext = new ExtendedModel(model, List.of(new Effect.Term(e, v)));
        String text = RobotFile.format(ext.toDescription());
        assertTrue(text.contains("\"model_angle\""), text);
        ExtendedModel back = ExtendedModel.of(RobotFile.parse("x.robot.json", text), "x.robot.json");
        assertEquals(e.label(), back.terms().get(0).effect().label());
        PoseConditions c = PoseConditions.NONE;
        for (double[] q : model.randomConfigurations(10, 8))
            assertEquals(0, ext.tool(q, Pose.IDENTITY, c).distanceTo(back.tool(q, Pose.IDENTITY, c)), 1e-12);
        double[] q = new double[6];
        q[1] = 0.3;
        q[2] = 0.3;                                          // θ3 = 0: the curve's value at the arm angle, not at q3
        double[] g = new double[v.length], h = new double[v.length];
        e.regressor(q, c, g);
        e.regressor(new double[6], c, h);
        org.junit.jupiter.api.Assertions.assertArrayEquals(h, g, 1e-15);
    }
}
