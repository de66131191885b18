package org.robopro.app.demo;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.PoseConditions;
import org.robopro.calibration.simulation.PoseSampler;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellFile;
import org.robopro.models.Vec3;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

/** The demo controller's true robot: realistic error size, the concealed effect, the nominal model for the controller. */
class DemoControllerTest {
    static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");
    static final Pose TORCH = WeldProgram.torch(CellFile.shipped("irb2000-welding"));

    @Test
    void robot_severalSeeds_flangeErrorBetween5And15MmAndEffectDrawn() {
        KinematicModel nominal = KinematicModel.build(IRB2000);
        List<double[]> poses = new PoseSampler(nominal).sample(50, new Random(99));
        for (long seed = 1; seed <= 4; seed++) {
            DemoController.Truth[] t = new DemoController.Truth[1];
            DemoController.Robot r = DemoController.robot(IRB2000, TORCH, seed, ConcealedEffect.DEFAULT, 2e-5, t);
            assertTrue(t[0].errorRmsM() >= 0.005 * 0.9 && t[0].errorRmsM() <= 0.015 * 1.1, "seed " + seed + ": " + t[0].errorRmsM());
            assertTrue(t[0].effect().label().startsWith(ConcealedEffect.DEFAULT), t[0].effect().label());
            double sum = 0;
            for (double[] q : poses) {
                assertEquals(0, r.nominalFlange(q).distanceTo(nominal.flange(q)), 1e-12, "the controller knows only the nominal model");
                sum += Math.pow(r.truth().flange(q).distanceTo(nominal.flange(q)), 2);
                // The tracker reads the torch tip (not the controller's notion of it) in its own frame.
                Vec3 reading = r.measure(q, PoseConditions.NONE, new Random(1));
                Vec3 tip = DemoController.TRACKER_T_BASE.apply(r.truth().tool(q, PoseConditions.NONE).position());
                assertEquals(0, reading.minus(tip).norm(), 2e-4, "noise of 0.02 mm per axis");
                assertEquals(0, r.truth().flangeTtool().distanceTo(TORCH), 1e-12);
            }
            double rms = Math.sqrt(sum / poses.size());
            assertTrue(rms > 0.004 && rms < 0.02, "the tracker sees mm-level errors: " + rms);
        }
    }

    @Test
    void robot_noneEffect_noEffectAndSameSeedSameRobot() {
        DemoController.Truth[] a = new DemoController.Truth[1], b = new DemoController.Truth[1];
        DemoController.Robot ra = DemoController.robot(IRB2000, TORCH, 5, "none", 2e-5, a);
        DemoController.Robot rb = DemoController.robot(IRB2000, TORCH, 5, "none", 2e-5, b);
        assertNull(a[0].effect());
        double[] q = {0.1, 0.2, 0.1, 0.3, 0.5, -0.2};
        assertEquals(0, ra.truth().flange(q).distanceTo(rb.truth().flange(q)), 1e-15);
        assertTrue(ra.truth().effects().isEmpty());
        assertThrows(IllegalArgumentException.class, () -> DemoController.robot(IRB2000, TORCH, 5, "gremlins", 2e-5, null));
    }
}
