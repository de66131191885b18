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
    void confOf_quadrantNumbers_followAbbDefinitionAndBoundariesDoNotFlipWithRounding() {
        InverseKinematics ik = InverseKinematics.of(KinematicModel.build(ReferenceRobots.irb2000()));
        // ABB's confdata: quadrant 0 is 0..90 deg, 1 is 90..180 deg, -1 is 0..-90 deg, -2 is -90..-180 deg (floor(q / 90 deg)).
        double[][] degAndQuadrant = {{45, 0}, {135, 1}, {200, 2}, {300, 3}, {-45, -1}, {-135, -2}, {-200, -3}, {-300, -4},
                {0, 0}, {90, 1}, {-90, -1}, {180, 2}, {-180, -2}};
        for (double[] dq : degAndQuadrant) {
            double r = Math.toRadians(dq[0]);
            ConfData c = ik.confOf(new double[] {0, 0, 0, r, 0.5, r});
            assertEquals((int) dq[1], c.cf4(), dq[0] + " deg on axis 4");
            assertEquals((int) dq[1], c.cf6(), dq[0] + " deg on axis 6");
        }
        // A joint on a boundary, as rounding leaves it: -0.0, a few ulps or 1e-9 rad to either side, is on it.
        for (double base : new double[] {0, Math.PI / 2, -Math.PI / 2, Math.PI}) {
            int expected = (int) Math.round(base / (Math.PI / 2));
            for (double noise : new double[] {0, -0.0, 1e-15, -1e-15, 6.3e-15, -6.3e-15, 1e-9, -1e-9, 5e-7, -5e-7}) {
                ConfData c = ik.confOf(new double[] {base + noise, 0, 0, base + noise, 0.5, base + noise});
                assertEquals(new ConfData(expected, expected, expected, 0), c, "boundary " + Math.toDegrees(base) + " deg, noise " + noise);
            }
            // beyond the tolerance the quadrant below is meant
            ConfData below = ik.confOf(new double[] {0, 0, 0, base - 1e-5, 0.5, base - 1e-5});
            assertEquals(expected - 1, below.cf4(), "1e-5 rad below " + Math.toDegrees(base) + " deg");
            assertEquals(expected - 1, below.cf6());
        }
        // Axis 5 at 0 (the wrist singularity) is positive whatever the rounding; clearly negative sets bit 0 of cfx.
        for (double q5 : new double[] {0, -0.0, -1e-15, -1e-9, 1e-9})
            assertEquals(0, ik.confOf(new double[] {0, 0, 0, 0, q5, 0}).cfx() & 1, "axis 5 at " + q5);
        assertEquals(1, ik.confOf(new double[] {0, 0, 0, 0, -1e-4, 0}).cfx() & 1);
    }

    @Test
    void solveWithConf_targetTaughtOnQuadrantBoundaries_reachedInItsConfigurationWhicheverSideRoundingPutsIt() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        InverseKinematics ik = InverseKinematics.of(m);
        Random rnd = new Random(31);
        // Taught with axes 4 and 6 at 0 (the workbench's ready pose jogged), and at +-90 deg.
        double[][] taught = {{Math.toRadians(10), Math.toRadians(29.86), Math.toRadians(8.39), 0, Math.toRadians(56.6), 0},
                {0, Math.toRadians(25), Math.toRadians(5), Math.PI / 2, Math.toRadians(60), -Math.PI / 2}};
        for (double[] q0 : taught) {
            ConfData conf = ik.confOf(q0);
            Pose exact = m.flange(q0);
            boolean below4 = false, above4 = false;
            for (int k = 0; k < 60; k++) {
                // what a robtarget written at RAPID's precision and read back can be: the pose moved by about 1e-9 m and rad
                org.robopro.models.Vec3 axis = new org.robopro.models.Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
                Pose rounded = Pose.translation(1e-9 * rnd.nextGaussian(), 1e-9 * rnd.nextGaussian(), 1e-9 * rnd.nextGaussian())
                        .times(exact).times(Pose.rotAxis(axis, 1e-9));
                double[] nearest = ik.solveNear(rounded, q0).orElseThrow().q();
                double d4 = nearest[3] - q0[3];
                if (d4 < 0) below4 = true;
                if (d4 > 0) above4 = true;
                Optional<IkSolution> s = ik.solveWithConf(rounded, conf);
                assertTrue(s.isPresent(), "taught at " + java.util.Arrays.toString(q0) + " in " + conf + ": the rounded pose has no solution in it");
                for (int j = 0; j < 6; j++) assertEquals(q0[j], s.get().q()[j], 1e-6, "joint " + (j + 1));
                assertTrue(ik.inConfiguration(s.get().q(), conf));
            }
            assertTrue(below4 && above4, "the perturbations put axis 4 on both sides of its boundary");
        }
    }

    @Test
    void inConfiguration_jointOnBoundaryInBothQuadrants_clearlyInsideOneOnlyThere() {
        InverseKinematics ik = InverseKinematics.of(KinematicModel.build(ReferenceRobots.irb2000()));
        double[] onZero = {0.2, 0.3, 0.1, -1e-9, 0.8, 1e-12};
        assertTrue(ik.inConfiguration(onZero, new ConfData(0, 0, 0, 0)));
        assertTrue(ik.inConfiguration(onZero, new ConfData(0, -1, 0, 0)));
        assertTrue(ik.inConfiguration(onZero, new ConfData(0, -1, -1, 0)));
        assertFalse(ik.inConfiguration(onZero, new ConfData(0, 1, 0, 0)), "90 deg away");
        assertFalse(ik.inConfiguration(onZero, new ConfData(0, 0, 0, 4)), "the arm bits of cfx must agree");
        double[] inside = {0.2, 0.3, 0.1, -1e-3, 0.8, 0.4};
        assertTrue(ik.inConfiguration(inside, new ConfData(0, -1, 0, 0)));
        assertFalse(ik.inConfiguration(inside, new ConfData(0, 0, 0, 0)), "1e-3 rad is inside quadrant -1, not on its boundary");
        // axis 5 at the wrist singularity: both signs
        double[] wrist = {0.2, 0.3, 0.1, 0.3, -1e-9, 0.4};
        assertTrue(ik.inConfiguration(wrist, new ConfData(0, 0, 0, 0)));
        assertTrue(ik.inConfiguration(wrist, new ConfData(0, 0, 0, 1)));
        assertFalse(ik.inConfiguration(new double[] {0.2, 0.3, 0.1, 0.3, -0.1, 0.4}, new ConfData(0, 0, 0, 0)));
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
