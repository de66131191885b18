package org.robopro.kinematics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;

class InverseKinematicsTest {

    private static void assertReaches(KinematicModel m, Pose target, double[] q, double tol, String msg) {
        Pose p = m.flange(q);
        assertTrue(p.distanceTo(target) < tol && p.angleTo(target) < tol,
                msg + ": " + p + " vs " + target + " (" + p.distanceTo(target) + " m, " + p.angleTo(target) + " rad)");
    }

    @Test
    void solveAll_shippedRobots_everySolutionReproducesPoseAndOriginalIsAmongThem() {
        for (RobotDescription d : ReferenceRobots.all()) {
            KinematicModel m = KinematicModel.build(d);
            InverseKinematics ik = InverseKinematics.of(m);
            assertTrue(ik.hasExactClosedForm(), d.name());
            for (double[] q : m.randomConfigurations(100, 21)) {
                Pose target = m.flange(q);
                List<IkSolution> sols = ik.solveAll(target);
                assertTrue(sols.size() >= 1, d.name());
                boolean found = false;
                for (IkSolution s : sols) {
                    assertReaches(m, target, s.q(), 1e-9, d.name());
                    assertEquals(m.withinLimits(s.q()), s.withinLimits());
                    double dmax = 0;
                    for (int i = 0; i < 6; i++) dmax = Math.max(dmax, Math.abs(s.q()[i] - q[i]));
                    if (dmax < 1e-7) found = true;
                }
                assertTrue(found, d.name() + ": original q among the solutions " + java.util.Arrays.toString(q));
            }
        }
    }

    @Test
    void solveAll_irb2000ReachablePose_eightDistinctConfigurationsWhenLimitsAllow() {
        // A PUMA has 8 solutions for a generic pose with wide limits.
        KinematicModel m = KinematicModel.build(ReferenceRobots.puma560());
        InverseKinematics ik = InverseKinematics.of(m);
        double[][] th = new double[8][6];
        double[] t = new double[12];
        m.flange(new double[] {0.3, 0.4, -0.5, 0.6, 0.7, 0.8}, m.newWorkspace(), t);
        assertEquals(8, ik.closedFormThetas(t, th));
        java.util.Set<ConfData> confs = new java.util.HashSet<>();
        for (int i = 0; i < 8; i++) {
            double[] q = m.q(th[i]);
            assertReaches(m, Se3.toPose(t), q, 1e-9, "solution " + i);
            confs.add(new ConfData(0, 0, 0, ik.confOf(q).cfx()));
        }
        assertEquals(8, confs.size(), "the 8 solutions have the 8 cfx values");
    }

    @Test
    void confOf_irb2000ZeroPosition_frontFrontPositive() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        InverseKinematics ik = InverseKinematics.of(m);
        assertEquals(new ConfData(0, 0, 0, 0), ik.confOf(new double[] {0, 0, 0, 0, 0.1, 0}));
        assertEquals(new ConfData(-1, 1, -2, 1), ik.confOf(new double[] {-0.1, 0, 0, 1.6, -0.1, -3.0}));
        // axis 1 turned half a turn with the arm leaning back: wrist centre still in front
        assertEquals(0, ik.confOf(new double[] {0, 0.5, 0.2, 0, 0.3, 0}).cfx() & 4);
    }

    @Test
    void solveWithConf_roundTripKeepsConfiguration() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2400());
        InverseKinematics ik = InverseKinematics.of(m);
        for (double[] q : m.randomConfigurations(50, 22)) {
            ConfData conf = ik.confOf(q);
            Optional<IkSolution> s = ik.solveWithConf(m.flange(q), conf);
            assertTrue(s.isPresent(), "conf " + conf);
            assertEquals(conf, s.get().conf());
            assertReaches(m, m.flange(q), s.get().q(), 1e-9, "conf solution");
        }
    }

    @Test
    void solveNear_perturbedIrb2000_convergesFromNominalClosedForm() {
        KinematicModel nominal = KinematicModel.build(ReferenceRobots.irb2000());
        Random rnd = new Random(23);
        double[] p = nominal.parameterValues();
        for (int i = 0; i < p.length; i++)
            p[i] += (nominal.parameters().get(i).kind() == ModelParameter.Kind.ROTATION ? 2e-3 : 2e-3) * rnd.nextGaussian();
        // written to a file and read back: the calibrated model no longer has a spherical wrist
        KinematicModel cal = KinematicModel.build(nominal.withParameterValues(p).toDescription());
        InverseKinematics ik = InverseKinematics.of(cal);
        assertFalse(ik.hasExactClosedForm());
        assertTrue(ik.hasClosedForm());
        for (double[] q : cal.randomConfigurations(40, 24)) {
            Pose target = cal.flange(q);
            Optional<IkSolution> s = ik.solveNear(target, q);
            assertTrue(s.isPresent(), "q " + java.util.Arrays.toString(q));
            assertReaches(cal, target, s.get().q(), 1e-9, "calibrated");
            for (int i = 0; i < 6; i++) assertEquals(q[i], s.get().q()[i], 1e-6);
            for (IkSolution all : ik.solveAll(target)) assertReaches(cal, target, all.q(), 1e-9, "calibrated solveAll");
        }
    }

    @Test
    void solveNumerical_randomRobotWithoutClosedForm_reachesPoseFromNearbySeed() {
        Random rnd = new Random(25);
        int ok = 0;
        for (int r = 0; r < 10; r++) {
            KinematicModel m = KinematicModel.build(ReferenceRobots.randomRobot(rnd, 6, false));
            InverseKinematics ik = InverseKinematics.of(m);
            for (double[] q : m.randomConfigurations(5, 26)) {
                double[] seed = q.clone();
                for (int i = 0; i < 6; i++) seed[i] += 0.2 * rnd.nextGaussian();
                InverseKinematics.NumericalOutcome o = ik.solveNumerical(m.flange(q), seed);
                if (o.solution().isPresent()) {
                    ok++;
                    assertReaches(m, m.flange(q), o.solution().get().q(), 1e-9, "numerical");
                    assertTrue(m.withinLimits(o.solution().get().q()));
                }
            }
        }
        assertTrue(ok >= 45, "converged " + ok + " of 50");
    }

    @Test
    void solveAll_unreachablePose_empty() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        assertTrue(InverseKinematics.of(m).solveAll(Pose.translation(5, 0, 1)).isEmpty());
    }

    @Test
    void singularityMeasure_wristStraight_nearZero() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        InverseKinematics ik = InverseKinematics.of(m);
        double straight = ik.singularityMeasure(new double[] {0.1, 0.2, 0.1, 0.3, 0, 0.4});
        double bent = ik.singularityMeasure(new double[] {0.1, 0.2, 0.1, 0.3, 0.8, 0.4});
        assertTrue(straight < 1e-9, "axis 5 at zero aligns axes 4 and 6: " + straight);
        assertTrue(bent > 1e-3, "bent wrist " + bent);
    }
}
