package org.robopro.calibration;

import java.util.List;
import java.util.Random;
import java.util.function.UnaryOperator;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.world.Campaign;
import org.robopro.world.Rigid;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * The recovery tests' truth: a robot drawn by the independent world simulator (org.robopro.world,
 * its own kinematics and errors, nothing shared with this module), measured, written as a
 * measurement file and read back by the product's reader. The truth is compared through what the
 * world predicts, never through this module's parameters.
 */
public final class WorldCampaigns {
    private WorldCampaigns() { }

    /** A measured world robot: the campaign as read, and the truth behind it. */
    public record Sim(RobotDescription nominal, WorldRobot world, Campaign.Result campaign, MeasurementSet train,
                      MeasurementSet validation) {
        public double sigmaM() { return campaign.plan().sigmaM(); }

        public double sigmaRotRad() { return campaign.plan().sigmaRotRad(); }

        /** √3 σ: the RMS a perfect model leaves on noisy 3-D points. */
        public double floorM() { return Math.sqrt(3) * sigmaM(); }

        /** The true (noise-free) pose of the measured target in the instrument frame at controller values q, no effects. */
        public Pose truePose(double[] q) {
            Rigid t = world.target(q, ones(q.length), Double.NaN, 0, 0);
            double[] p = t.p(), w = t.quaternion();
            return Pose.fromQuaternion(w[0], w[1], w[2], w[3], p[0], p[1], p[2]);
        }

        /**
         * RMS distance, m, between the nominal robot file's prediction (measured point nominally
         * 100 mm along the flange z axis) and the true target, both in base coordinates, over the
         * training poses: how wrong the robot file is.
         */
        public double nominalErrorRmsM(org.robopro.kinematics.KinematicModel nominalModel) {
            WorldRobot inBase = world.withInstrument(Rigid.IDENTITY);
            double s = 0;
            for (Measurement m : train.rows()) {
                double[] p = inBase.target(m.q(), ones(m.dof()), Double.NaN, 0, 0).p();
                var n = nominalModel.flange(m.q()).times(Pose.translation(0, 0, 0.1)).position();
                s += Math.pow(Math.hypot(Math.hypot(p[0] - n.x(), p[1] - n.y()), p[2] - n.z()), 2);
            }
            return Math.sqrt(s / train.size());
        }
    }

    static int[] ones(int n) {
        int[] d = new int[n];
        java.util.Arrays.fill(d, 1);
        return d;
    }

    /**
     * A robot file's robot with geometric errors only (world defaults: axis points ~1 mm, axis
     * directions and zero offsets ~0.1°, target ~100 mm off the flange), measured with
     * {@code plan}; {@code baseFrame}: the instrument measures in the robot base frame.
     */
    public static Sim geometric(RobotDescription nominal, long seed, boolean baseFrame, UnaryOperator<Campaign.Plan> plan) {
        WorldRobot w = Scenario.baseRobot(nominal, new Random(seed), 1e-3, Math.toRadians(0.1));
        if (baseFrame) w = w.withInstrument(Rigid.IDENTITY);
        return measure(nominal, w, plan.apply(Campaign.Plan.defaults(seed)));
    }

    /** A world scenario's trial (its robot and campaign), read back as a user's file would be. */
    public static Sim of(Scenario.Trial t) {
        RobotDescription nominal = org.robopro.models.RobotLibrary.shipped(t.scenario().robot());
        return read(nominal, t.world(), t.campaign());
    }

    /** Measures a world robot and reads the file back as a user's file would be. */
    public static Sim measure(RobotDescription nominal, WorldRobot w, Campaign.Plan plan) {
        return read(nominal, w, Campaign.run(w, nominal, plan));
    }

    private static Sim read(RobotDescription nominal, WorldRobot w, Campaign.Result c) {
        List<org.robopro.models.JointType> types = nominal.joints().stream().map(JointDescription::type).toList();
        MeasurementSet all = MeasurementReader.parse("world-" + nominal.name() + ".csv", c.text(), types);
        MeasurementSet val = all.split(Measurement.Split.VALIDATE);
        return new Sim(nominal, w, c, all.split(Measurement.Split.TRAIN), val.size() == 0 ? null : val);
    }

    /** RMS distance, m, between the calibrated prediction of the measured point and the world's noise-free truth at the validation poses. */
    public static double modelErrorRms(Sim s, CalibrationResult r) {
        double sum = 0;
        Pose inst = r.instrumentTbase() == null ? Pose.IDENTITY : r.instrumentTbase();
        for (Measurement m : s.validation().rows()) {
            var predicted = inst.times(r.calibrated().flange(m.q())).times(r.flangeTtool()).position();
            sum += Math.pow(predicted.minus(s.truePose(m.q()).position()).norm(), 2);
        }
        return Math.sqrt(sum / s.validation().size());
    }

    /** RMS angle, rad, between calibrated and true target orientations at the validation poses. */
    public static double modelAngleRms(Sim s, CalibrationResult r) {
        double sum = 0;
        Pose inst = r.instrumentTbase() == null ? Pose.IDENTITY : r.instrumentTbase();
        for (Measurement m : s.validation().rows()) {
            var predicted = inst.times(r.calibrated().flange(m.q())).times(r.flangeTtool());
            sum += Math.pow(predicted.angleTo(s.truePose(m.q())), 2);
        }
        return Math.sqrt(sum / s.validation().size());
    }
}
