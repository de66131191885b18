package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class RobotKinematicsTest {
    private final RobotDescription irb = RobotLibrary.load("irb2000");

    @Test
    void flange_zeroJoints_isTheDescribedFlange() {
        for (RobotKinematics k : new RobotKinematics[] {RobotKinematics.of(irb), new ScrewKinematics(irb)}) {
            Pose f = k.flange(new double[6]);
            Pose expected = Pose.fromFrame(irb.flange());
            assertEquals(0, f.distanceTo(expected), 1e-9, k.implementation());
            assertEquals(0, f.angleTo(expected), 1e-9, k.implementation());
        }
    }

    @Test
    void flange_q2Forward_movesWristForwardAndDown() {
        // Positive q2 tilts the upper arm forward (robots.md); the parallel linkage keeps the forearm level.
        RobotKinematics k = new ScrewKinematics(irb);
        double[] q = {0, Math.toRadians(30), 0, 0, 0, 0};
        Pose f = k.flange(q);
        double l = 1.490 - 0.780;
        assertEquals(1.0 + l * Math.sin(Math.toRadians(30)), f.x(), 1e-9);
        assertEquals(1.615 - l * (1 - Math.cos(Math.toRadians(30))), f.z(), 1e-9);
        assertEquals(0, f.angleTo(Pose.fromFrame(irb.flange())), 1e-9, "forearm stays level under q2");
    }

    @Test
    void solveNear_randomReachablePoses_roundTrips() {
        Random rnd = new Random(7);
        for (RobotKinematics k : new RobotKinematics[] {RobotKinematics.of(irb), new ScrewKinematics(irb)}) {
            for (int i = 0; i < 20; i++) {
                double[] q = new double[6];
                for (int j = 0; j < 6; j++) q[j] = (rnd.nextDouble() - 0.5) * Math.toRadians(80);
                Pose target = k.flange(q);
                double[] seed = q.clone();
                for (int j = 0; j < 6; j++) seed[j] += (rnd.nextDouble() - 0.5) * 0.1;
                Optional<double[]> sol = k.solveNear(target, seed);
                assertTrue(sol.isPresent(), k.implementation() + " sample " + i);
                Pose back = k.flange(sol.get());
                assertEquals(0, back.distanceTo(target), 1e-6);
                assertEquals(0, back.angleTo(target), 1e-6);
            }
        }
    }

    @Test
    void solveNear_farOutside_isEmpty() {
        RobotKinematics k = new ScrewKinematics(irb);
        assertTrue(k.solveNear(Pose.translation(4, 0, 1).times(Pose.fromFrame(irb.flange()).inverse()
                .times(Pose.fromFrame(irb.flange())).times(Pose.rotY(Math.PI / 2))), new double[6]).isEmpty());
    }

    @Test
    void linkDisplacements_matchFlange() {
        RobotKinematics k = RobotKinematics.of(irb);
        double[] q = {0.3, -0.2, 0.4, 1.0, -0.5, 2.0};
        Pose[] d = k.linkDisplacements(q);
        Pose viaLinks = d[6].times(Pose.fromFrame(irb.flange()));
        assertEquals(0, viaLinks.distanceTo(k.flange(q)), 1e-9);
        assertEquals(0, viaLinks.angleTo(k.flange(q)), 1e-9);
        assertEquals(0, d[0].distanceTo(Pose.IDENTITY), 0);
    }

    @Test
    void firstLimitViolation_joint3OutOfRange_isIndex2() {
        RobotKinematics k = RobotKinematics.of(irb);
        assertEquals(-1, k.firstLimitViolation(new double[6]));
        assertEquals(2, k.firstLimitViolation(new double[] {0, 0, Math.toRadians(61), 0, 0, 0}));
    }
}
