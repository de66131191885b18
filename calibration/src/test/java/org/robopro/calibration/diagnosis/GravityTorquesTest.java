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

    @Test
    void torques_verticalFirstAxis_zeroAndPayloadRaisesShoulderTorque() {
        double[] q = {0.3, 0.4, -0.2, 0.1, 0.5, 0};
        double[] t0 = g.torques(q, 0), t10 = g.torques(q, 10);
        assertEquals(0, t0[0], 1e-9);
        assertTrue(Math.abs(t10[1]) > Math.abs(t0[1]) + 10, t0[1] + " vs " + t10[1]);
    }
}
