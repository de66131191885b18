package org.robopro.programs.compensation;

import java.util.Arrays;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.Calibrator;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Campaign;
import org.robopro.world.Rigid;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * The compensation tests' real robot: an IRB 2000 drawn by the independent world simulator
 * (org.robopro.world: its own kinematics, nothing shared with kinematics or calibration) with
 * geometric errors, measured in its base frame (200 poses, σ 0.02 mm, the target about 100 mm off
 * the flange), the file read back by the product's reader and calibrated. Where the real robot
 * puts its target is asked of the world, never of a calibrated model.
 */
public record WorldCalibration(WorldRobot world, CalibrationResult result, double sigmaM) {
    public static final RobotDescription IRB2000 = RobotLibrary.shipped("irb2000");

    private static final Map<Long, WorldCalibration> CACHE = new ConcurrentHashMap<>();

    /** The world robot of {@code seed}, measured and calibrated (computed once per seed). */
    public static WorldCalibration of(long seed) {
        return CACHE.computeIfAbsent(seed, WorldCalibration::draw);
    }

    private static WorldCalibration draw(long seed) {
        WorldRobot w = Scenario.baseRobot(IRB2000, new Random(seed), 1e-3, Math.toRadians(0.1)).withInstrument(Rigid.IDENTITY);
        Campaign.Plan plan = Campaign.Plan.defaults(seed).withPoses(200, 0).withDirColumns(false).withConditionColumns(false);
        Campaign.Result c = Campaign.run(w, IRB2000, plan);
        MeasurementSet set = MeasurementReader.parse("world.csv", c.text(), IRB2000.joints().stream().map(j -> j.type()).toList());
        return new WorldCalibration(w, Calibrator.calibrate(KinematicModel.build(IRB2000), set, null), plan.sigmaM());
    }

    /** The calibrated model: a model other than the nominal one, for the compensation's own consistency checks. */
    public KinematicModel calibrated() { return result.calibrated(); }

    /** Where the world's robot really puts its measured target (base frame, m) at controller values q. */
    public double[] truePoint(double[] q) {
        int[] dir = new int[q.length];
        Arrays.fill(dir, 1);
        return world.target(q, dir, Double.NaN, 0, 0).p();
    }

    /** √3 σ: the RMS a perfect model leaves on the campaign's noisy points. */
    public double floorM() { return Math.sqrt(3) * sigmaM; }

    /** The nominal measured point on the flange, where the campaign's target nominally was. */
    public static Pose nominalTarget() { return Pose.translation(0, 0, 0.1); }
}
