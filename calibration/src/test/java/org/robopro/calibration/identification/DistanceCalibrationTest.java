package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.Rigid;
import org.robopro.world.WorldRobot;

/**
 * Distance-only data (a draw-wire sensor, a tracker in distance mode): the length from a fixed
 * anchor to the measured point at every pose, on a robot drawn by the independent world simulator.
 * The distances are computed here from the world's noise-free point; the file is read by the
 * product's reader. Recovery is judged on what distances can show: lengths to the anchor at poses
 * the fit never saw, and the distance between the point's places at two poses (the arm's shape,
 * which no rigid motion of the whole set-up changes).
 */
public class DistanceCalibrationTest {
    public static final double SIGMA = 0.02e-3;
    /** The anchor in the world's robot base frame, m: on the floor in front of the robot. */
    static final double[] ANCHOR = {1.3, -0.4, 0.05};

    public record Truth(RobotDescription nominal, WorldRobot world, List<Measurement> train, List<Measurement> validate) {
        double[] point(double[] q) {
            int[] dir = new int[q.length];
            java.util.Arrays.fill(dir, 1);
            return world.target(q, dir, Double.NaN, 0, 0).p();
        }

        double distance(double[] q) {
            double[] p = point(q);
            return Math.sqrt(Math.pow(p[0] - ANCHOR[0], 2) + Math.pow(p[1] - ANCHOR[1], 2) + Math.pow(p[2] - ANCHOR[2], 2));
        }
    }

    public static Truth truth(long seed, int poses) {
        RobotDescription nominal = RobotLibrary.shipped("irb2400");
        WorldCampaigns.Sim sim = WorldCampaigns.geometric(nominal, seed, true, p -> p.withPoses(poses, 60).withSigma(0));
        return new Truth(nominal, sim.world().withInstrument(Rigid.IDENTITY), sim.train().rows(), sim.validation().rows());
    }

    public static String file(Truth t, long seed, boolean giveAnchor) {
        Random rng = new Random(seed);
        StringBuilder b = new StringBuilder("# robopro-measurements 1\n# robot: irb2400\n# length-unit: mm\n# angle-unit: deg\n"
                + "# instrument: draw-wire sensor\n");
        if (giveAnchor) b.append(String.format(Locale.ROOT, "# anchor: %.6f, %.6f, %.6f\n", ANCHOR[0] * 1e3, ANCHOR[1] * 1e3, ANCHOR[2] * 1e3));
        b.append("pose,q1,q2,q3,q4,q5,q6,distance\n");
        for (Measurement m : t.train()) {
            b.append(m.poseId());
            for (double q : m.q()) b.append(String.format(Locale.ROOT, ",%.12f", Math.toDegrees(q)));
            b.append(String.format(Locale.ROOT, ",%.6f\n", (t.distance(m.q()) + SIGMA * rng.nextGaussian()) * 1e3));
        }
        return b.toString();
    }

    /** RMS of the calibrated model's anchor distance minus the world's at the validation poses, m. */
    static double distanceErrorRms(Truth t, CalibrationResult r) {
        double s = 0;
        for (Measurement m : t.validate()) {
            Vec3 p = r.calibrated().flange(m.q()).apply(r.toolPoints().get(0));
            s += Math.pow(p.minus(r.anchor()).norm() - t.distance(m.q()), 2);
        }
        return Math.sqrt(s / t.validate().size());
    }

    /** RMS error of |p(q_a) − p(q_b)| over consecutive validation poses: the arm's shape, free of any placement. */
    static double shapeErrorRms(Truth t, CalibrationResult r, KinematicModel model, boolean calibrated) {
        double s = 0;
        List<Measurement> v = t.validate();
        Vec3 tool = calibrated ? r.toolPoints().get(0) : new Vec3(0, 0, 0.1);
        for (int i = 0; i + 1 < v.size(); i++) {
            double[] qa = v.get(i).q(), qb = v.get(i + 1).q();
            double pred = model.flange(qa).apply(tool).minus(model.flange(qb).apply(tool)).norm();
            double[] ta = t.point(qa), tb = t.point(qb);
            double truth = Math.sqrt(Math.pow(ta[0] - tb[0], 2) + Math.pow(ta[1] - tb[1], 2) + Math.pow(ta[2] - tb[2], 2));
            s += Math.pow(pred - truth, 2);
        }
        return Math.sqrt(s / (v.size() - 1));
    }

    static MeasurementSet read(Truth t, String text) {
        return MeasurementReader.parse("wire.csv", text, t.nominal().joints().stream().map(JointDescription::type).toList());
    }

    @Test
    void distances_recoverTheArmToTheNoiseFloor_withTheAnchorUnknown() {
        Truth t = truth(41, 150);
        MeasurementSet s = read(t, file(t, 5, false));
        KinematicModel nominal = KinematicModel.build(t.nominal());
        CalibrationResult r = Calibrator.calibrate(nominal, s, null);
        double rms = r.trainRmsM(), val = distanceErrorRms(t, r);
        double shape = shapeErrorRms(t, r, r.calibrated(), true), shapeNominal = shapeErrorRms(t, r, nominal, false);
        System.out.printf(Locale.ROOT, "distances: train RMS %.4f mm (sigma %.4f), validation distance error vs truth %.4f mm, "
                        + "shape error %.4f mm (nominal %.3f mm), anchor %s, fixed %s, concerns %s%n", rms * 1e3, SIGMA * 1e3, val * 1e3,
                shape * 1e3, shapeNominal * 1e3, r.anchor(), MultiPointCalibrationTest.fixedNames(r),
                Trust.assess(r, s).stream().map(Trust.Concern::parameter).toList());
        // One residual per pose: the floor is σ itself.
        assertTrue(rms > 0.7 * SIGMA && rms < 1.2 * SIGMA, "training RMS " + rms * 1e3 + " mm vs sigma " + SIGMA * 1e3);
        assertTrue(val < SIGMA, "validation distances vs truth " + val * 1e3 + " mm");
        assertTrue(shape < 3 * SIGMA && shape < 0.05 * shapeNominal, "shape error " + shape * 1e3 + " mm, nominal " + shapeNominal * 1e3);
        // The robot's placement relative to the anchor is not seen: its parameters stay nominal, and the warning says so.
        List<String> fixed = MultiPointCalibrationTest.fixedNames(r);
        assertTrue(fixed.contains("j1.d") || fixed.contains("j1.offset"), "base placement fixed: " + fixed);
        List<String> words = org.robopro.calibration.report.CalibrationReport.warnings(r, s, null);
        assertTrue(words.stream().anyMatch(w -> w.startsWith("distance-only data: ") && w.contains("not observable")
                && w.contains("j1.d") && w.contains("arm's shape")), words.toString());
    }

    @Test
    void distances_withTheAnchorGiven_keepIt() {
        Truth t = truth(42, 150);
        MeasurementSet s = read(t, file(t, 6, true));
        CalibrationResult r = Calibrator.calibrate(KinematicModel.build(t.nominal()), s, null);
        assertTrue(r.anchorGiven());
        assertTrue(r.anchor().minus(new Vec3(ANCHOR[0], ANCHOR[1], ANCHOR[2])).norm() < 1e-9, "anchor kept: " + r.anchor());
        double val = distanceErrorRms(t, r);
        System.out.printf(Locale.ROOT, "distances, anchor given: train RMS %.4f mm, validation distance error %.4f mm%n",
                r.trainRmsM() * 1e3, val * 1e3);
        assertTrue(r.trainRmsM() < 1.2 * SIGMA && val < SIGMA, "validation distances vs truth " + val * 1e3 + " mm");
        // Given in the base frame, the anchor makes the robot's placement observable: identified, not kept nominal.
        List<String> fixed = MultiPointCalibrationTest.fixedNames(r);
        assertTrue(!fixed.contains("j1.d") && !fixed.contains("base.tx"), "placement identified: " + fixed);
    }
}
