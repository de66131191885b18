package org.robopro.kinematics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

class KinematicModelTest {

    private static void assertPoseEquals(Pose expected, Pose actual, double tolM, double tolRad, String msg) {
        assertTrue(expected.distanceTo(actual) < tolM, msg + ": position " + expected + " vs " + actual);
        assertTrue(expected.angleTo(actual) < tolRad, msg + ": orientation " + expected + " vs " + actual);
    }

    @Test
    void build_puma560FromJointAxes_sameFkAsStandardDhTable() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.puma560());
        Random rnd = new Random(1);
        for (int i = 0; i < 200; i++) {
            double[] q = new double[6];
            for (int k = 0; k < 6; k++) q[k] = (rnd.nextDouble() * 2 - 1) * Math.PI;
            Pose dh = ReferenceRobots.standardDh(ReferenceRobots.PUMA_DH, q);
            assertPoseEquals(dh, m.flange(q), 1e-12, 1e-12, "q " + java.util.Arrays.toString(q));
        }
    }

    @Test
    void build_irb2400_sameFkAsModifiedDhTableWithCoupling() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2400());
        double[] zero = new double[6];
        // The table's flange frame (ROS tool0 convention) differs from robopro's by a constant rotation.
        Pose mdhTflange = ReferenceRobots.modifiedDh(ReferenceRobots.IRB2400_MDH, zero).inverse().times(m.flange(zero));
        assertTrue(mdhTflange.position().norm() < 1e-12, "flange origins agree at zero: " + mdhTflange);
        Random rnd = new Random(2);
        for (int i = 0; i < 200; i++) {
            double[] q = new double[6];
            for (int k = 0; k < 6; k++) q[k] = m.qMin(k) + rnd.nextDouble() * (m.qMax(k) - m.qMin(k));
            double[] theta = m.theta(q);
            assertEquals(q[2] - q[1], theta[2], 1e-15);
            Pose ref = ReferenceRobots.modifiedDh(ReferenceRobots.IRB2400_MDH, theta).times(mdhTflange);
            assertPoseEquals(ref, m.flange(q), 1e-12, 1e-12, "q " + java.util.Arrays.toString(q));
        }
    }

    @Test
    void flange_irb2000AtZero_isDescribedFlange() {
        RobotDescription d = ReferenceRobots.irb2000();
        Pose f = KinematicModel.build(d).flange(new double[6]);
        assertPoseEquals(Pose.fromFrame(d.flange()), f, 1e-15, 1e-15, "zero position");
    }

    @Test
    void flange_irb2000ParallelLinkage_forearmStaysLevelWhenOnlyQ2Moves() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        Pose p = m.flange(new double[] {0, 0.5, 0, 0, 0, 0});
        // q3 is the forearm's angle to the horizontal: unchanged forearm, flange z still along +x.
        assertEquals(1.0, p.zAxis().x(), 1e-12);
        assertEquals(1.615 + 0.71 * (Math.cos(0.5) - 1), p.z(), 1e-12);
    }

    @Test
    void theta_q_inverseCouplingRoundTrip() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        double[] q = {0.1, 0.2, -0.3, 0.4, 0.5, 0.6};
        assertArrayEquals(q, m.q(m.theta(q)), 1e-15);
    }

    @Test
    void parameters_shippedRobots_30NamedWithFullRankFromRulesAlone() {
        for (RobotDescription d : ReferenceRobots.all()) {
            KinematicModel m = KinematicModel.build(d);
            assertEquals(30, m.parameters().size(), d.name());
            assertEquals(30, m.identificationRank(), d.name());
            assertEquals("", m.identifiabilityNote(), d.name() + " needed no numerical repair");
            assertTrue(m.identificationConditionNumber() < 1e4, d.name() + " cond " + m.identificationConditionNumber());
        }
        List<String> names = KinematicModel.build(ReferenceRobots.irb2000()).parameters().stream().map(ModelParameter::name).toList();
        assertTrue(names.containsAll(List.of("base.tx", "base.rx", "j2.beta", "j3.d", "flange.tz")), names.toString());
    }

    @Test
    void parameters_randomRevoluteRobots_fullRank4RPlus6() {
        Random rnd = new Random(3);
        for (int i = 0; i < 30; i++) {
            int n = 2 + rnd.nextInt(6);
            KinematicModel m = KinematicModel.build(ReferenceRobots.randomRobot(rnd, n, false));
            assertEquals(4 * n + 6, m.parameters().size(), "robot " + i);
            assertEquals(4 * n + 6, m.identificationRank(), "robot " + i + " " + m.identifiabilityNote());
        }
    }

    @Test
    void parameters_randomRobotsWithPrismaticJoints_fullRank4RPlus2PPlus6() {
        Random rnd = new Random(4);
        for (int i = 0; i < 30; i++) {
            int n = 2 + rnd.nextInt(5);
            KinematicModel m = KinematicModel.build(ReferenceRobots.randomRobot(rnd, n, true));
            assertEquals(m.expectedParameterCount(), m.parameters().size(), "robot " + i + " " + m.identifiabilityNote());
            assertEquals(m.expectedParameterCount(), m.identificationRank(), "robot " + i + " " + m.identifiabilityNote());
        }
    }

    @Test
    void build_randomRobots_zeroPositionReproducesDescribedFlange() {
        Random rnd = new Random(5);
        for (int i = 0; i < 30; i++) {
            RobotDescription d = ReferenceRobots.randomRobot(rnd, 1 + rnd.nextInt(7), true);
            Pose f = KinematicModel.build(d).flange(new double[d.dof()]);
            assertPoseEquals(Pose.fromFrame(d.flange()), f, 1e-12, 1e-12, "robot " + i);
        }
    }

    @Test
    void flange_fastPath_matchesLinkFramesAndElementWalk() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        KinematicModel.Workspace ws = m.newWorkspace();
        double[] out = new double[12], pos = new double[3], jac = new double[3 * 30];
        for (double[] q : m.randomConfigurations(20, 6)) {
            m.flange(q, ws, out);
            Pose fast = Se3.toPose(out);
            Pose[] frames = m.linkFrames(q);
            assertEquals(8, frames.length);
            assertPoseEquals(frames[7], fast, 1e-14, 1e-14, "link frames");
            m.pointJacobian(q, new double[3], ws, pos, jac);
            assertArrayEquals(new double[] {out[3], out[7], out[11]}, pos, 1e-14);
        }
    }

    private static void assertFastFkMatchesReference(KinematicModel m, long seed, String what) {
        KinematicModel.Workspace ws = m.newWorkspace();
        double[] out = new double[12];
        double[][] qs = m.randomConfigurations(40, seed);
        Random rnd = new Random(seed);
        for (int i = 0; i < qs.length; i++) {
            double[] q = qs[i];
            if (i % 4 == 3) for (int k = 0; k < q.length; k++) q[k] += 2 * Math.PI * (rnd.nextInt(7) - 3); // every quadrant, big angles
            if (i == qs.length - 1) q[0] = 3e5; // beyond the polynomial's reduction range
            m.flange(q, ws, out);
            double[] ref = m.flangeReference(q);
            // folding the offset into 3e5 rad rounds the angle to its ulp (6e-11): looser there
            double tol = i == qs.length - 1 ? 1e-9 : 1e-13;
            for (int j = 0; j < 12; j++)
                assertEquals(ref[j], out[j], tol, what + " entry " + j + " at q " + java.util.Arrays.toString(q));
        }
    }

    @Test
    void flange_fastPathNominalAndCalibrated_matchesElementByElementReference() {
        for (RobotDescription d : ReferenceRobots.all()) {
            KinematicModel m = KinematicModel.build(d);
            assertFastFkMatchesReference(m, 3, d.name());
            double[] p = m.parameterValues();
            Random rnd = new Random(4);
            for (int i = 0; i < p.length; i++) p[i] += 1e-3 * rnd.nextGaussian();
            assertFastFkMatchesReference(m.withParameterValues(p), 5, d.name() + " calibrated");
        }
        Random rnd = new Random(8);
        for (int i = 0; i < 10; i++) {
            RobotDescription d = ReferenceRobots.randomRobot(rnd, 3 + rnd.nextInt(5), true);
            assertFastFkMatchesReference(KinematicModel.build(d), 10 + i, "random robot " + i);
        }
    }

    @Test
    void flange_dhRows_takeTheRxShapedProductOnlyWhileExact() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        // four DH rows (j1, j3, j4, j5) plus the Hayati row j2 -> j3 while its beta is exactly 0
        assertTrue(m.fastRxCount() >= 4, "R_X-shaped rows: " + m.fastRxCount());
        double[] p = m.parameterValues();
        int beta = m.parameters().stream().map(ModelParameter::name).toList().indexOf("j2.beta");
        p[beta] += 1e-4;
        assertEquals(m.fastRxCount() - 1, m.withParameterValues(p).fastRxCount(), "a calibrated beta makes that row general");
    }

    @Test
    void linkFrames_irb2000_zAxesAreJointAxes() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        double[] q = {0.3, -0.2, 0.4, 1.0, -0.5, 2.0};
        Pose[] f = m.linkFrames(q);
        // Joint 1 is about base z through the origin.
        assertEquals(1, f[1].zAxis().z(), 1e-15);
        assertEquals(0, f[1].position().norm(), 1e-15);
        // Joint 5's axis is perpendicular to joints 4 and 6 and all three meet at the wrist centre.
        assertEquals(0, f[5].zAxis().dot(f[4].zAxis()), 1e-12);
        assertEquals(0, f[5].zAxis().dot(f[6].zAxis()), 1e-12);
        assertEquals(0, f[6].position().minus(f[5].position()).norm(), 1e-12);
    }

    @Test
    void geometricJacobian_matchesFiniteDifferencesThroughCoupling() {
        for (RobotDescription d : ReferenceRobots.all()) {
            KinematicModel m = KinematicModel.build(d);
            for (double[] q : m.randomConfigurations(5, 7)) {
                double[][] j = m.geometricJacobian(q);
                Pose p0 = m.flange(q);
                double h = 1e-7;
                for (int k = 0; k < 6; k++) {
                    double[] qp = q.clone(), qm = q.clone();
                    qp[k] += h;
                    qm[k] -= h;
                    Pose pp = m.flange(qp), pm = m.flange(qm);
                    double[] fd = twistDifference(pp, pm, 2 * h);
                    for (int r = 0; r < 6; r++) assertEquals(fd[r], j[r][k], 1e-7, d.name() + " row " + r + " col " + k);
                }
                assertTrue(p0 != null);
            }
        }
    }

    /** (position, small rotation) difference (a - b) / h, rotation in base coordinates. */
    static double[] twistDifference(Pose a, Pose b, double h) {
        Vec3 w = a.times(b.inverse()).rotationVector();
        return new double[] {(a.x() - b.x()) / h, (a.y() - b.y()) / h, (a.z() - b.z()) / h, w.x() / h, w.y() / h, w.z() / h};
    }

    @Test
    void poseJacobian_matchesFiniteDifferencesOverParameters() {
        Random rnd = new Random(8);
        List<RobotDescription> robots = new java.util.ArrayList<>(ReferenceRobots.all());
        robots.add(ReferenceRobots.randomRobot(rnd, 5, true));
        Pose tool = Pose.fromQuaternion(0.9, 0.1, -0.2, 0.3, 0.05, -0.02, 0.2);
        for (RobotDescription d : robots) {
            KinematicModel m = KinematicModel.build(d);
            int np = m.parameters().size();
            KinematicModel.Workspace ws = m.newWorkspace();
            double[] pose = new double[12], jac = new double[6 * np];
            double[] p0 = m.parameterValues();
            for (double[] q : m.randomConfigurations(3, 9)) {
                m.poseJacobian(q, tool, ws, pose, jac);
                assertPoseEquals(m.flange(q).times(tool), Se3.toPose(pose), 1e-13, 1e-13, "tool pose");
                double h = 1e-7;
                for (int c = 0; c < np; c++) {
                    double[] pp = p0.clone(), pm = p0.clone();
                    pp[c] += h;
                    pm[c] -= h;
                    Pose a = m.withParameterValues(pp).flange(q).times(tool), b = m.withParameterValues(pm).flange(q).times(tool);
                    double[] fd = twistDifference(a, b, 2 * h);
                    for (int r = 0; r < 6; r++)
                        assertEquals(fd[r], jac[r * np + c], 1e-7, d.name() + " " + m.parameters().get(c).name() + " row " + r);
                }
            }
        }
    }

    @Test
    void pointJacobian_matchesPoseJacobianOfTranslatedTool() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2400());
        int np = m.parameters().size();
        KinematicModel.Workspace ws = m.newWorkspace();
        double[] point = {0.01, 0.02, 0.15};
        double[] pos = new double[3], jp = new double[3 * np], pose = new double[12], jf = new double[6 * np];
        double[] q = m.randomConfigurations(1, 10)[0];
        m.pointJacobian(q, point, ws, pos, jp);
        m.poseJacobian(q, Pose.translation(point[0], point[1], point[2]), ws, pose, jf);
        assertArrayEquals(new double[] {pose[3], pose[7], pose[11]}, pos, 1e-15);
        for (int i = 0; i < 3 * np; i++) assertEquals(jf[i], jp[i], 1e-15);
    }

    @Test
    void toDescription_perturbedModel_rebuildGivesSameFk() {
        Random rnd = new Random(11);
        List<RobotDescription> robots = new java.util.ArrayList<>(ReferenceRobots.all());
        for (int i = 0; i < 5; i++) robots.add(ReferenceRobots.randomRobot(rnd, 3 + rnd.nextInt(4), true));
        for (RobotDescription d : robots) {
            KinematicModel m = KinematicModel.build(d);
            double[] p = m.parameterValues();
            for (int i = 0; i < p.length; i++)
                p[i] += (m.parameters().get(i).kind() == ModelParameter.Kind.ROTATION ? 1e-3 : 1e-3) * rnd.nextGaussian();
            KinematicModel cal = m.withParameterValues(p);
            KinematicModel rebuilt = KinematicModel.build(cal.toDescription());
            for (double[] q : m.randomConfigurations(20, 12))
                assertPoseEquals(cal.flange(q), rebuilt.flange(q), 1e-12, 1e-12, d.name());
        }
    }

    @Test
    void withParameterValues_sameValues_sameFk() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        KinematicModel same = m.withParameterValues(m.parameterValues());
        double[] q = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
        assertEquals(m.flange(q), same.flange(q));
        assertThrows(IllegalArgumentException.class, () -> m.withParameterValues(new double[3]));
    }

    @Test
    void withinLimits_irb2000_respectsControllerRanges() {
        KinematicModel m = KinematicModel.build(ReferenceRobots.irb2000());
        assertTrue(m.withinLimits(new double[6]));
        assertFalse(m.withinLimits(new double[] {0, 0, Math.toRadians(61), 0, 0, 0}));
    }

    @Test
    void build_zeroAxis_refusedNamingTheField() {
        RobotDescription d = ReferenceRobots.irb2000();
        List<JointDescription> js = new java.util.ArrayList<>(d.joints());
        JointDescription j = js.get(3);
        js.set(3, new JointDescription(j.name(), JointType.REVOLUTE, j.point(), Vec3.ZERO, j.min(), j.max(), j.maxSpeed()));
        InputException e = assertThrows(InputException.class, () -> KinematicModel.build(d.withJointsAndFlange(js, d.flange())));
        assertEquals("joints[4].axis", e.field());
    }
}
