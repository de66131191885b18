package org.robopro.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class PhysicsTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    static final double G = 9.80665;

    /** The file's masses exactly, all joints rigid except where stiffness is set. */
    static WorldRobot.Compliance exact(RobotDescription r) {
        return WorldRobot.Compliance.fromFile(r.massModel().orElseThrow(), r.dof(), 0, new java.util.Random(0) {
            @Override public double nextGaussian() { return 0; }
        });
    }

    @Test
    void gravityTorquesAtZeroByHand() {
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[3]).withCompliance(exact(IRB2000));
        double[] tau = w.gravityTorques(w.arm(), new double[6], 0);
        // Joint 1 is vertical: gravity has no moment about it.
        assertEquals(0, tau[0], 1e-9);
        // Joint 2 (axis +y through z 780): upper arm straight above (no moment); forearm 35 kg at x 300 mm
        // and wrist 6 kg at x 850 mm: r × F about +y = -x * (-m g) = m g x, positive (pulls the arm forward and down).
        assertEquals(35 * G * 0.300 + 6 * G * 0.850, tau[1], 1e-9);
        // Joint 3 (axis +y through z 1490): the same two masses.
        assertEquals(35 * G * 0.300 + 6 * G * 0.850, tau[2], 1e-9);
        // Joint 5 (axis +y through (850, 0, 1615)): the wrist's centre is on the axis.
        assertEquals(0, tau[4], 1e-9);
        // A 10 kg payload at the flange (x 1000 mm) adds 10 g * 1.0 to joint 2 and 10 g * 0.15 to joint 5.
        double[] withLoad = w.gravityTorques(w.arm(), new double[6], 10);
        assertEquals(tau[1] + 10 * G * 1.0, withLoad[1], 1e-9);
        assertEquals(10 * G * 0.15, withLoad[4], 1e-9);
    }

    @Test
    void drivesYieldToTheTorqueTheyCarryThroughTheParallelLinkage() {
        WorldRobot rigid = WorldRobot.nominal(IRB2000, new double[3]);
        int[] dir = {1, 1, 1, 1, 1, 1};
        double[] a = rigid.target(new double[6], dir, Double.NaN, 0, 10).p();
        // Upper arm vertical: the whole weight outboard of joint 3 hangs straight over joint 2, so the
        // upper-arm drive carries tau_q2 = tau_theta2 - tau_theta3 = 0 (virtual work through theta3 = q3 - q2):
        // a soft drive 2 does not move the flange.
        WorldRobot soft2 = rigid.withCompliance(exact(IRB2000).withStiffness(1, 1e6));
        double[] b = soft2.target(new double[6], dir, Double.NaN, 0, 10).p();
        assertEquals(0, Rigid.norm(Rigid.minus(b, a)), 1e-12);
        // Drive 3 carries the forearm, wrist and payload: it yields by tau/k and the forearm turns about
        // +y at joint 3: the flange (1000 mm ahead, 125 mm above joint 3) goes down and a little forward.
        WorldRobot soft3 = rigid.withCompliance(exact(IRB2000).withStiffness(2, 1e6));
        double[] c = soft3.target(new double[6], dir, Double.NaN, 0, 10).p();
        double dq = (35 * G * 0.300 + 6 * G * 0.850 + 10 * G * 1.0) / 1e6;
        // rotation about +y by dq: (x, z) -> (x cos + z sin, -x sin + z cos)
        assertEquals(-1.000 * Math.sin(dq) + 0.125 * (Math.cos(dq) - 1), c[2] - a[2], 1e-12);
        assertEquals(1.000 * (Math.cos(dq) - 1) + 0.125 * Math.sin(dq), c[0] - a[0], 1e-12);
        assertTrue(c[2] < a[2]);
        // Upper arm leaning 30° forward: drive 2 now carries the upper arm (45 kg, 355 mm up the arm) and the
        // weight outboard of joint 3 times joint 3's lead over joint 2.
        double q2 = Math.toRadians(30);
        double[] q = {0, q2, 0, 0, 0, 0};
        double[] tau = soft2.gravityTorques(soft2.arm(), WorldRobot.times(soft2.coupling(), q), 10);
        assertEquals(((35 + 6 + 10) * 0.710 + 45 * 0.355) * G * Math.sin(q2), tau[1] - tau[2], 1e-9);
    }

    /**
     * Warm air over cool bends a tracker's beam down (concave toward the ground), so the point is seen
     * higher, by the tangent–chord offset of the arc: κL²/2 with κ = (n − 1)/T·dT/dz/n (the refraction
     * coefficient of trigonometric levelling). The instrument 10 m along the base's x, level with the
     * flange; 2 K/m at 20 °C: κ = 2.7e-4 / 293.15 · 2 / 1.00027 = 1.8417e-6 /m, so 9.2 µm higher at
     * 10 m, four times that at 20 m, and a cool layer over warm air the other way.
     */
    @Test
    void warmAirOverCoolShowsThePointHigher() {
        double z = 1.615;
        for (double far : new double[] {10, 20})
            for (double grad : new double[] {2, -2}) {
                WorldRobot still = WorldRobot.nominal(IRB2000, new double[3])
                        .withInstrument(Rigid.translation(1 + far, 0, z).inverse());
                WorldRobot bent = still.withRefraction(new WorldRobot.Refraction(new double[] {0}, new double[] {grad}));
                int[] dir = {1, 1, 1, 1, 1, 1};
                double[] p0 = still.target(new double[6], dir, 20, 100, 0).p(), p1 = bent.target(new double[6], dir, 20, 100, 0).p();
                double kappa = 2.7e-4 / 293.15 * grad / (1 + 2.7e-4);
                // seen from the instrument, the shift is along the instrument's z (its frame here is the base's, moved)
                assertEquals(kappa * far * far / 2, p1[2] - p0[2], 1e-3 * Math.abs(kappa * far * far / 2));
                assertEquals(p0[1], p1[1], 1e-12);
                // the distance the instrument reads is the sight's length, unchanged
                assertEquals(Math.hypot(p0[0], p0[2]), Math.hypot(p1[0], p1[2]), 1e-12);
            }
    }

    @Test
    void thermalGrowthLengthensTheArmWithTemperature() {
        double[] alpha = new double[7];
        Arrays.fill(alpha, 20e-6);
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[3]).withThermal(new WorldRobot.Thermal(20, alpha, new double[3], new double[3]));
        int[] dir = {1, 1, 1, 1, 1, 1};
        double[] cold = w.target(new double[6], dir, 20, 0, 0).p(), warm = w.target(new double[6], dir, 30, 0, 0).p();
        // Uniform 20e-6/K over 10 K: every coordinate of the zero pose grows by 2e-4 about the base origin.
        assertEquals(1.000 * 2e-4, warm[0] - cold[0], 1e-12);
        assertEquals(1.615 * 2e-4, warm[2] - cold[2], 1e-12);
    }

    @Test
    void targetHolderGrowsAlongItselfWithTemperature() {
        // Only the aluminium holder grows: 100 mm x 23e-6/K x 10 K = 23 µm along the flange-to-target offset, at any pose.
        WorldRobot.Thermal holder = new WorldRobot.Thermal(20, new double[7], new double[3], new double[3])
                .withHolderAlpha(WorldRobot.Thermal.ALUMINIUM_HOLDER_ALPHA);
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[] {0, 0, 0.1}).withThermal(holder);
        WorldRobot flange = WorldRobot.nominal(IRB2000, new double[3]);
        int[] dir = {1, 1, 1, 1, 1, 1};
        for (double[] q : List.of(new double[6], new double[] {0.3, -0.2, 0.4, 1.0, -0.7, 2.0})) {
            double[] cold = w.target(q, dir, 20, 0, 0).p(), warm = w.target(q, dir, 30, 0, 0).p();
            double[] along = Rigid.minus(cold, flange.target(q, dir, 20, 0, 0).p()); // the holder, flange to target
            assertEquals(0.1, Rigid.norm(along), 1e-12);
            double[] grow = Rigid.minus(warm, cold);
            assertEquals(23e-6, Rigid.norm(grow), 1e-12);
            assertEquals(23e-6 * 0.1, Rigid.dot(grow, along), 1e-15);
        }
        // without the holder's coefficient the target does not move with temperature when no link grows
        WorldRobot still = WorldRobot.nominal(IRB2000, new double[] {0, 0, 0.1})
                .withThermal(new WorldRobot.Thermal(20, new double[7], new double[3], new double[3]));
        assertEquals(0, Rigid.norm(Rigid.minus(still.target(new double[6], dir, 30, 0, 0).p(), still.target(new double[6], dir, 20, 0, 0).p())), 0);
    }

    @Test
    void driveErrorsActBeforeTheCoupling() {
        // A gear-ratio error on drive 2 of the parallel-arm IRB 2000 turns the upper arm and, through
        // theta3 = q3 - q2, turns the forearm back: the forearm stays horizontal.
        WorldRobot w = WorldRobot.nominal(IRB2000, new double[3]).withErrors(List.of(new JointError.Scale(1, 0.01)));
        double q2 = Math.toRadians(30);
        double[] p = w.target(new double[] {0, q2, 0, 0, 0, 0}, new int[6], Double.NaN, 0, 0).p();
        double a = 1.01 * q2;
        assertEquals(0.710 * Math.sin(a) + 1.0, p[0], 1e-12);
        assertEquals(0.780 + 0.710 * Math.cos(a) + 0.125, p[2], 1e-12);
    }
}
