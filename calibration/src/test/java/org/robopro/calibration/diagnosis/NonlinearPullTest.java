package org.robopro.calibration.diagnosis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.ToDoubleFunction;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.models.RobotLibrary;

/**
 * One drive pulled by another joint's angle, against truth written here: a world campaign with
 * geometric errors only (org.robopro.world, nothing shared with {@link Effect}) whose joint-4
 * readings are then made to lie by δ4(q). A cross-coupling of gears is linear, δ4 = κ·q6; a dress
 * pack or cable that tightens as the wrist winds up pulls the drive by a stiff, non-linear function
 * of the other joint (a spring that stiffens as it stretches), which a coupling holds only in its
 * linear part. The first must be named a coupling; the second must not.
 */
class NonlinearPullTest {

    /** The set with joint {@code j}'s reading replaced by what a controller reads when its output is off by δ(q_out). */
    static MeasurementSet readOff(MeasurementSet set, int j, ToDoubleFunction<double[]> delta) {
        List<Measurement> rows = new ArrayList<>();
        for (Measurement m : set.rows()) {
            double[] q = m.q().clone();
            q[j] = Math.toRadians(Math.rint(Math.toDegrees(q[j] - delta.applyAsDouble(m.q())) * 1e4) / 1e4);
            rows.add(m.withQ(q));
        }
        return new MeasurementSet(set.source(), set.metadata(), set.frame(), rows, set.pointNames(), set.anchor());
    }

    /**
     * A hose that pulls joint 4 once joint 6 has wound up past 60°, with a stiffness that grows as
     * it stretches: δ4 = 0.1°·((|q6| − 60°)/100°)³·sign q6 beyond 60°, nothing below. Linear in
     * nothing, so no coupling j4←j6 may be claimed; the structure is located on joint 4.
     */
    @Test
    void hoseTighteningWithTheWrist_isNotACoupling() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 8, false, p -> p.withPoses(300, 100).withSigma(1e-5));
        double slack = Math.toRadians(60), scale = Math.toRadians(100), amp = Math.toRadians(0.1);
        ToDoubleFunction<double[]> hose = q -> {
            double x = Math.abs(q[5]) - slack;
            return x > 0 ? amp * Math.pow(x / scale, 3) * Math.signum(q[5]) : 0;
        };
        Diagnosis d = Diagnoser.diagnose(desc, readOff(c.train(), 3, hose), readOff(c.validation(), 3, hose));
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(!d.located().isEmpty() || d.effects().stream().anyMatch(f -> f.effect().isFallback()), "nothing located: " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.3 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * A true gear cross-coupling, δ6 = κ·q4 with κ = 6·10⁻⁴ (joint 6's shaft runs through axis 4),
     * is still named a coupling j6←j4 (its smooth rival ties and the simpler form stays).
     */
    @Test
    void linearCoupling_isStillNamed() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 9, false, p -> p.withPoses(300, 100).withSigma(1e-5));
        ToDoubleFunction<double[]> kappa = q -> 6e-4 * q[3];
        Diagnosis d = Diagnoser.diagnose(desc, readOff(c.train(), 5, kappa), readOff(c.validation(), 5, kappa));
        assertEquals(List.of("joint-coupling j6<-j4"), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /**
     * The same error the other way round, δ4 = κ·q6: joint 6's drive has no path to joint 4's, so no
     * coupling is claimed; the error of joint 4 that follows joint 6 is modelled by a fallback.
     */
    @Test
    void couplingFromAJointBeyondItsTarget_isNotClaimed() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 9, false, p -> p.withPoses(300, 100).withSigma(1e-5));
        ToDoubleFunction<double[]> kappa = q -> 6e-4 * q[5];
        Diagnosis d = Diagnoser.diagnose(desc, readOff(c.train(), 3, kappa), readOff(c.validation(), 3, kappa));
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(d.effects().stream().anyMatch(f -> f.effect().isFallback() && f.effect().joint() == 3),
                "not modelled: " + d.effects().stream().map(f -> f.effect().label()).toList());
        assertTrue(d.finalValidateRmsM() < 1.15 * c.floorM(), d.finalValidateRmsM() + " vs floor " + c.floorM());
    }

    /** The smooth error following another joint reads and writes its source joint, and its regressor follows that joint. */
    @Test
    void smoothFollowingAnotherJoint_roundTrips() {
        Effect e = Effect.smoothFollowing(3, 5, -3, 3, 7);
        assertEquals("joint-smooth-error j4 (following j6)", e.label());
        assertEquals(List.of(4, 6), e.joints1());
        double[] g = new double[7], b = new double[7], q = {0.1, 0.2, 0.3, 0.4, 0.5, 1.7};
        e.regressor(q, org.robopro.calibration.PoseConditions.NONE, g);
        Effect.bspline(1.7, -3, 3, b);
        for (int i = 0; i < 7; i++) assertEquals(b[i], g[i], 0);
        var model = org.robopro.kinematics.KinematicModel.build(RobotLibrary.shipped("irb2000"));
        double[] v = {1e-4, 2e-4, -1e-4, 0, 3e-4, 1e-4, -2e-4};
        Effect back = Effect.fromDescription(e.describe(v), model, null, "x.json").effect();
        assertEquals(e.label(), back.label());
        assertEquals(5, back.angleJoint());
    }

    /**
     * A dress pack across the wrist: its bend over joint 5 is a spring, so drive 5 gives way
     * through its compliance by δ5 = −c5·k5·(q5 − q5n), linear in q5 (a scale error's form); its
     * tension pulls joint 4 by a torque that follows both q4 and q5 (the hose wraps around axis 4
     * more as the wrist bends): δ4 = A·sin(q4 − φ)·(1 − cos q5). Joint 5's error alone is a
     * scale error, but the structure beside it on joint 4 follows joint 5 too, and no family
     * explains it: one load across the wrist makes both, so no gear-ratio error of joint 5 is
     * claimed (its smooth fallback models the same shape).
     */
    @Test
    void dressPackBendAndPull_isNotAScaleErrorOfJoint5() {
        var desc = RobotLibrary.shipped("irb2000");
        WorldCampaigns.Sim c = WorldCampaigns.geometric(desc, 11, false, p -> p.withPoses(240, 80).withSigma(1.5e-5));
        double bend = 2.5e-4, q5n = Math.toRadians(3), amp = Math.toRadians(0.03), phase = Math.toRadians(40);
        ToDoubleFunction<double[]> spring = q -> -bend * (q[4] - q5n);
        ToDoubleFunction<double[]> pull = q -> amp * Math.sin(q[3] - phase) * (1 - Math.cos(q[4]));
        MeasurementSet train = readOff(readOff(c.train(), 4, spring), 3, pull);
        MeasurementSet val = readOff(readOff(c.validation(), 4, spring), 3, pull);
        Diagnosis d = Diagnoser.diagnose(desc, train, val);
        System.out.println("dress pack bend and pull: " + d.effects().stream().map(f -> f.effect().label()).toList()
                + " validation " + d.finalValidateRmsM() / c.floorM() + " x floor, geometric " + d.geometricValidateRmsM() / c.floorM());
        assertEquals(List.of(), HeldOutFormsTest.families(d), "notes " + d.notes());
        assertTrue(d.geometricValidateRmsM() > 2 * c.floorM(), "the load matters: " + d.geometricValidateRmsM() / c.floorM());
        assertTrue(d.finalValidateRmsM() < 0.6 * d.geometricValidateRmsM(), "the fallbacks model it: " + d.finalValidateRmsM() / c.floorM());
    }
}
