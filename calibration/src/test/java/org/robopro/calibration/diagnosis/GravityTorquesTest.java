package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class GravityTorquesTest {
    private final RobotDescription robot = RobotLibrary.shipped("irb2000");
    private final KinematicModel model = KinematicModel.build(robot);
    private final GravityTorques g = new GravityTorques(model, robot.massModel().orElseThrow());

    @Test
    void torques_randomPoses_equalMinusGradientOfPotentialInModelAngles() {
        Random r = new Random(3);
        double h = 1e-6;
        for (double[] q : model.randomConfigurations(10, 11)) {
            double payload = 10 * r.nextDouble();
            double[] tau = g.torques(q, payload);
            double[] theta = model.theta(q);
            for (int j = 0; j < model.dof(); j++) {
                double[] tp = theta.clone(), tm = theta.clone();
                tp[j] += h;
                tm[j] -= h;
                double dv = (g.potentialEnergy(model.q(tp), payload) - g.potentialEnergy(model.q(tm), payload)) / (2 * h);
                assertEquals(-dv, tau[j], 1e-5 * (1 + Math.abs(tau[j])), "joint " + (j + 1));
            }
        }
    }

    /** Split by mass, the joint's own torques add up to {@link GravityTorques#torques} and the drive's to the drive's; joint 2 of the parallel arm differs by joint 3's. */
    @Test
    void torquesByMass_addUpToTheWholeTorque_jointsAndDrives() {
        double[] byMass = new double[g.massCount()];
        for (double[] q : model.randomConfigurations(5, 23)) {
            double[] tau = g.torques(q, 7), drive = g.driveTorques(q, 7);
            for (int j = 0; j < model.dof(); j++) {
                g.jointTorquesByMass(q, 7, j, byMass);
                assertEquals(tau[j], java.util.Arrays.stream(byMass).sum(), 1e-9 * (1 + Math.abs(tau[j])), "joint " + (j + 1));
                g.driveTorquesByMass(q, 7, j, byMass);
                assertEquals(drive[j], java.util.Arrays.stream(byMass).sum(), 1e-9 * (1 + Math.abs(drive[j])), "drive " + (j + 1));
            }
            assertEquals(tau[1] - tau[2], drive[1], 1e-9 * (1 + Math.abs(tau[1])), "θ3 = q3 − q2: drive 2 feels τ2 − τ3");
        }
    }

    @Test
    void torques_verticalFirstAxis_zeroAndPayloadRaisesShoulderTorque() {
        double[] q = {0.3, 0.4, -0.2, 0.1, 0.5, 0};
        double[] t0 = g.torques(q, 0), t10 = g.torques(q, 10);
        assertEquals(0, t0[0], 1e-9);
        assertTrue(Math.abs(t10[1]) > Math.abs(t0[1]) + 10, t0[1] + " vs " + t10[1]);
    }
    /**
     * The payload's centre moved along the flange's axes, at the IRB 2000's zero pose (flange at
     * (1000, 0, 1615) mm, its z along the base's +x, its x along −z; docs robots.md), 10 kg. Moved
     * 0.1 m out along the tool (flange z), its lever about each horizontal axis along y grows by 0.1 m:
     * τ = r × F · y = x·m·g, 9.80665 N·m more about joints 3 and 5; moved along the flange's x (down)
     * nothing. Drive 2 of the parallel arm carries none of it: θ3 = q3 − q2, so τ_q2 = τ_θ2 − τ_θ3
     * (virtual work), and both grow alike.
     */
    @Test
    void payloadCentreMovedAlongTheToolAddsItsLeverTimesTheWeight() {
        double[] q = new double[6], t = new double[4];
        double mg = 10 * 9.80665;
        g.payloadDriveTorques(q, 10, 4, t);
        assertEquals(0, t[1], 1e-9, "down the flange's x: no lever about joint 5");
        assertEquals(0, t[2], 1e-9, "along the flange's y (joint 5's own axis): no lever");
        assertEquals(0.1 * mg, t[3], 1e-6, "out along the tool");
        g.payloadDriveTorques(q, 10, 2, t);
        assertEquals(0.1 * mg, t[3], 1e-6, "drive 3 carries the forearm's side");
        g.payloadDriveTorques(q, 10, 1, t);
        assertEquals(0, t[3], 1e-6, "drive 2 of the parallel arm carries none of it");
        // the payload at the file's centre, as the whole torque less the arm's
        g.payloadDriveTorques(q, 10, 4, t);
        assertEquals(g.driveTorques(q, 10)[4] - g.driveTorques(q, 0)[4], t[0], 1e-9);
    }
}
