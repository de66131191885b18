package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class ArmTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");

    static double[] deg(double... d) {
        double[] r = new double[d.length];
        for (int i = 0; i < d.length; i++) r[i] = Math.toRadians(d[i]);
        return r;
    }

    /** Flange position of the nominal robot at controller values q (deg), through the controller's coupling. */
    static double[] flangeMm(RobotDescription robot, double... qDeg) {
        WorldRobot w = WorldRobot.nominal(robot, new double[3]);
        return Rigid.scale(w.target(deg(qDeg), new int[qDeg.length], Double.NaN, 0, 0).p(), 1e3);
    }

    @Test
    void zeroPoseIsTheFilesFlangeForEveryShippedRobot() {
        for (String name : RobotLibrary.shippedNames()) {
            RobotDescription r = RobotLibrary.shipped(name);
            Rigid f = Arm.of(r).flange(new double[r.dof()]);
            assertArrayEquals(r.flange().origin().toArray(), f.p(), 1e-12, name);
            assertArrayEquals(r.flange().zAxis().normalized().toArray(), f.axis(2), 1e-12, name);
            assertArrayEquals(r.flange().xAxis().normalized().toArray(), f.axis(0), 1e-12, name);
        }
    }

    @Test
    void irb2000HandComputedPoses() {
        // Axis 1 by 90°: the flange (1000, 0, 1615) turns about z to (0, 1000, 1615).
        assertArrayEquals(new double[] {0, 1000, 1615}, flangeMm(IRB2000, 90, 0, 0, 0, 0, 0), 1e-9);
        // Axis 2 by 90° (upper arm forward about +y, joint 3 from (0,0,1490) to (710,0,780)), axis 3 at 0:
        // the parallel linkage keeps the forearm horizontal (theta3 = q3 - q2 = -90°), so the flange is
        // joint 3 + (1000, 0, 125).
        assertArrayEquals(new double[] {1710, 0, 905}, flangeMm(IRB2000, 0, 90, 0, 0, 0, 0), 1e-9);
        // Axis 3 by -90° alone: forearm turned about +y at joint 3 by theta3 = -90°: (1000, 0, 125) -> (-125, 0, 1000)
        // ... rotation about +y by -90° maps (x, z) to (-z, x): (1000, 125) -> (-125, 1000).
        assertArrayEquals(new double[] {-125, 0, 1490 + 1000}, flangeMm(IRB2000, 0, 0, -90, 0, 0, 0), 1e-9);
        // Wrist: axis 5 by 90° about +y at (850, 0, 1615): the flange (150 mm ahead) drops to (850, 0, 1465).
        assertArrayEquals(new double[] {850, 0, 1465}, flangeMm(IRB2000, 0, 0, 0, 0, 90, 0), 1e-9);
        // Axis 4 and 6 turn about the forearm's own line: the flange origin does not move.
        assertArrayEquals(new double[] {1000, 0, 1615}, flangeMm(IRB2000, 0, 0, 0, 37, 0, -81), 1e-9);
    }

    @Test
    void flangeOrientationFollowsTheAxes() {
        // At zero the flange z is base +x and x is base -z; after axis 1 by 90°, z is base +y.
        Rigid f = Arm.of(IRB2000).flange(deg(90, 0, 0, 0, 0, 0));
        assertArrayEquals(new double[] {0, 1, 0}, f.axis(2), 1e-12);
        assertArrayEquals(new double[] {0, 0, -1}, f.axis(0), 1e-12);
    }

    @Test
    void rigidInverseQuaternionAndProduct() {
        Random r = new Random(3);
        for (int i = 0; i < 20; i++) {
            Rigid a = Rigid.rotation(Rigid.unit(Arm.gauss(r, 1)), 3 * r.nextGaussian(), Arm.gauss(r, 1));
            Rigid id = a.times(a.inverse());
            assertArrayEquals(Rigid.IDENTITY.r(), id.r(), 1e-12);
            assertArrayEquals(new double[3], id.p(), 1e-12);
            double[] q = a.quaternion();
            assertEquals(1, Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), 1e-12);
            // Rotating (1,0,0) by the quaternion equals the matrix's first column.
            double w = q[0], x = q[1], y = q[2], z = q[3];
            double[] col0 = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
            assertArrayEquals(a.axis(0), col0, 1e-12);
        }
    }

    @Test
    void grownLinksScaleTheirOwnSegmentsOnly() {
        Arm a = Arm.of(IRB2000);
        double[] strain = new double[IRB2000.dof() + 1];
        strain[2] = 1e-3; // the upper arm: joint 2 point (z 780) to joint 3 point (z 1490), 710 mm
        Arm g = a.grown(strain);
        assertEquals(0.780, g.points()[1][2], 1e-15);
        assertEquals(1.490 + 0.710e-3, g.points()[2][2], 1e-12);
        assertEquals(1.615 + 0.710e-3, g.flange().p()[2], 1e-12);
        assertEquals(1.000, g.flange().p()[0], 1e-12);
    }

    @Test
    void perturbedArmIsCloseButDifferent() {
        Arm a = Arm.of(IRB2000), b = a.perturbed(new Random(1), 1e-3, Math.toRadians(0.1));
        double d = Rigid.norm(Rigid.minus(a.flange(deg(10, 20, 30, 40, 50, 60)).p(), b.flange(deg(10, 20, 30, 40, 50, 60)).p()));
        assertTrue(d > 1e-4 && d < 2e-2, "flange moved by " + d + " m");
        for (double[] ax : b.axes()) assertEquals(1, Rigid.norm(ax), 1e-12);
    }

    @Test
    void lostMotionLagsTheMotor() {
        JointError.LostMotion b = new JointError.LostMotion(1, Math.toRadians(0.04));
        double[] q = deg(0, 30, 0, 0, 0, 0);
        // After a positive move the output has not yet caught up: it sits below the encoder's value.
        assertEquals(-Math.toRadians(0.02), b.delta(q, new int[] {1, 1, 1, 1, 1, 1}), 1e-15);
        assertEquals(Math.toRadians(0.02), b.delta(q, new int[] {1, -1, 1, 1, 1, 1}), 1e-15);
        // On the robot: after a positive move of axis 1 the flange is turned less than commanded.
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[3]).withErrors(List.of(new JointError.LostMotion(0, Math.toRadians(0.04))));
        double[] p = w.target(deg(30, 0, 0, 0, 0, 0), new int[] {1, 1, 1, 1, 1, 1}, Double.NaN, 0, 0).p();
        assertEquals(Math.toRadians(30 - 0.02), Math.atan2(p[1], p[0]), 1e-12);
    }
}
