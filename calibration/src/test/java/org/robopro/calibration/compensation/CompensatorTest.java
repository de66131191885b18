package org.robopro.calibration.compensation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;

class CompensatorTest {
    static final KinematicModel NOMINAL = KinematicModel.build(RobotLibrary.load("irb2000"));

    /** A real IRB 2000 drawn by the independent world simulator, measured in the base frame. */
    static WorldCampaigns.Sim world(long seed) {
        return WorldCampaigns.geometric(NOMINAL.description(), seed, true, p -> p.withPoses(200, 0));
    }

    /** A model other than the nominal one: the calibration of a world robot (for the compensator's own consistency). */
    static KinematicModel calibrated(long seed) {
        WorldCampaigns.Sim c = world(seed);
        return Calibrator.calibrate(NOMINAL, c.train(), null).calibrated();
    }

    @Test
    void compensate_calibratedModel_landsOnTrueRobotWithinNoiseFloor() {
        WorldCampaigns.Sim c = world(12);
        CalibrationResult r = Calibrator.calibrate(NOMINAL, c.train(), null);
        // The controller knows the nominal model and the nominal measured point; calibration knows better.
        Pose toolNominal = Pose.translation(0, 0, 0.1);
        Compensator comp = new Compensator(NOMINAL, r.calibrated(), toolNominal, r.flangeTtool());
        List<double[]> qs = new PoseSampler(NOMINAL).sample(100, new Random(4));
        double sumBefore = 0, sumAfter = 0;
        for (double[] qTrue : qs) {
            Pose target = NOMINAL.flange(qTrue).times(toolNominal); // reachable target poses
            // Uncompensated: the controller goes to q = IK_nominal(target).
            var plain = org.robopro.kinematics.InverseKinematics.of(NOMINAL).solveNear(target.times(toolNominal.inverse()), qTrue).orElseThrow();
            sumBefore += Math.pow(c.truePose(plain.q()).position().minus(target.position()).norm(), 2);
            Compensator.Result res = comp.compensate(target, qTrue);
            assertEquals(Compensator.Status.CONVERGED, res.status());
            assertTrue(res.residualM() < 1e-8);
            Pose reached = c.truePose(res.q()); // where the world's robot really puts the target
            sumAfter += Math.pow(reached.position().minus(target.position()).norm(), 2);
        }
        double before = Math.sqrt(sumBefore / qs.size()), after = Math.sqrt(sumAfter / qs.size());
        System.out.printf("compensation: %.3f mm -> %.4f mm (noise floor %.4f mm)%n", before * 1e3, after * 1e3, c.floorM() * 1e3);
        assertTrue(before > 3e-3, "uncompensated error " + before);
        assertTrue(after < c.floorM(), "compensated error " + after);
    }

    @Test
    void batch_fastPath_matchesReferencePath() {
        Pose tool = Pose.translation(0, 0, 0.1);
        Compensator comp = new Compensator(NOMINAL, calibrated(13), tool, tool);
        Compensator.Batch batch = comp.batch();
        List<double[]> qs = new PoseSampler(NOMINAL).sample(50, new Random(5));
        for (int i = 0; i < qs.size(); i++) {
            double[] q0 = qs.get(i);
            Pose target = NOMINAL.flange(q0).times(tool);
            // Half the targets seeded at their own joints (Newton from the seed), half far away (IK first).
            double[] seed = i % 2 == 0 ? q0.clone() : new double[6];
            Compensator.Result ref = comp.compensate(target, seed);
            if (ref.status() != Compensator.Status.CONVERGED) continue;
            double[] q = seed.clone(), cmd = new double[7], res = new double[2];
            double[] quat = target.quaternion();
            Compensator.Status st = batch.compensate(new double[] {target.x(), target.y(), target.z()}, quat, q, cmd, res);
            assertEquals(ref.status(), st);
            assertArrayEquals(ref.q(), q, 1e-7);
            assertEquals(ref.commanded().x(), cmd[0], 1e-7);
            assertEquals(ref.commanded().z(), cmd[2], 1e-7);
            assertEquals(0, ref.commanded().angleTo(Pose.fromQuaternion(cmd[3], cmd[4], cmd[5], cmd[6], 0, 0, 0)), 1e-7);
            assertTrue(res[0] < 1e-8 && res[1] < 1e-8);
        }
    }

    @Test
    void compensateWorld_robotPlacedInCell_returnsWorldCoordinates() {
        KinematicModel real = calibrated(14);
        Compensator comp = new Compensator(NOMINAL, real, Pose.IDENTITY, Pose.IDENTITY);
        Pose worldTbase = Pose.translation(2, 1, 0.5).times(Pose.rotZ(0.7));
        double[] q = {0.2, 0.1, -0.1, 0.3, 0.5, -0.2};
        Pose worldTarget = worldTbase.times(NOMINAL.flange(q));
        Compensator.Result w = comp.compensateWorld(worldTarget, worldTbase, q);
        Compensator.Result b = comp.compensate(worldTbase.inverse().times(worldTarget), q);
        assertEquals(0, w.commanded().distanceTo(worldTbase.times(b.commanded())), 1e-12);
        // The corrected model at the returned joints reaches the world target.
        assertEquals(0, worldTbase.times(real.flange(w.q())).distanceTo(worldTarget), 1e-8);
    }

    @Test
    void compensateWithTool_nominalToolGetsCalibratedTool_otherToolsKeptAsGiven() {
        KinematicModel real = calibrated(15);
        Pose toolNominal = Pose.translation(0, 0, 0.1), toolReal = Pose.translation(0.002, -0.001, 0.103);
        TargetCompensator comp = new Compensator(NOMINAL, real, toolNominal, toolReal);
        double[] q0 = {0.2, 0.1, -0.1, 0.3, 0.5, -0.2};
        Pose target = NOMINAL.flange(q0).times(toolNominal);
        // The tool calibrated for: the real robot with the real tool reaches the target.
        TargetCompensator.Result r = comp.compensate(target, toolNominal, q0);
        assertEquals(TargetCompensator.Status.CONVERGED, r.status());
        assertEquals(0, real.flange(r.q()).times(toolReal).distanceTo(target), 1e-8);
        assertTrue(real.flange(r.q()).times(toolNominal).distanceTo(target) > 1e-3, "the calibrated tool must matter");
        // Another tool is taken as given in both models.
        Pose other = Pose.translation(0, 0.05, 0.2).times(Pose.rotX(0.3));
        Pose target2 = NOMINAL.flange(q0).times(other);
        TargetCompensator.Result r2 = comp.compensate(target2, other, q0);
        assertEquals(TargetCompensator.Status.CONVERGED, r2.status());
        assertEquals(0, real.flange(r2.q()).times(other).distanceTo(target2), 1e-8);
        assertEquals(0, real.flange(r2.q()).times(other).angleTo(target2), 1e-8);
    }

    @Test
    void status_onlyConvergedIsOk() {
        for (TargetCompensator.Status s : TargetCompensator.Status.values())
            assertEquals(s == TargetCompensator.Status.CONVERGED, s.ok(), s.label());
        assertEquals("not converged", TargetCompensator.Status.NOT_CONVERGED.label());
    }

    @Test
    void batch_targetTurned180DegreesFromSeed_reachesTargetOrientation() {
        // The seed's nominal tool pose differs from the target by a half turn about the tool axis:
        // the rotation error's log is at 180°, where Log(R) cannot be read from the skew part.
        KinematicModel real = calibrated(16);
        Pose tool = Pose.translation(0, 0, 0.1);
        Compensator.Batch batch = new Compensator(NOMINAL, real, tool, tool).batch();
        List<double[]> qs = new PoseSampler(NOMINAL).sample(20, new Random(6));
        int checked = 0;
        for (double[] q0 : qs) {
            double[] turned = q0.clone();
            turned[5] += turned[5] > 0 ? -Math.PI : Math.PI;
            if (!NOMINAL.withinLimits(turned)) continue;
            Pose target = NOMINAL.flange(turned).times(tool);
            assertEquals(Math.PI, NOMINAL.flange(q0).times(tool).angleTo(target), 1e-9);
            double[] q = q0.clone(), cmd = new double[7], res = new double[2];
            TargetCompensator.Status st = batch.compensate(new double[] {target.x(), target.y(), target.z()}, target.quaternion(), q, cmd, res);
            // Joint 6 may end a full turn outside its limits (the branch is chosen on the seed's turn): say so, but land.
            assertTrue(st == TargetCompensator.Status.CONVERGED || st == TargetCompensator.Status.OUT_OF_LIMITS, st.label());
            Pose reached = real.flange(q).times(tool);
            assertEquals(0, reached.distanceTo(target), 1e-8);
            assertEquals(0, reached.angleTo(target), 1e-8, "the real robot's tool orientation");
            checked++;
        }
        assertTrue(checked >= 5, "too few poses with joint 6 turnable by 180°: " + checked);
    }
}
