package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.WorldCampaigns;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.world.Rigid;
import org.robopro.world.WorldRobot;

/**
 * Several reflectors on the flange, measured on a robot drawn by the independent world simulator
 * (its own product-of-exponentials kinematics and errors; nothing of this module's model): the
 * points are computed here from the world's flange, written as a measurement file in the long
 * form and read back by the product's reader. Recovery is judged against the world's noise-free
 * points and the world's flange rotations, never against this module's parameters.
 */
public class MultiPointCalibrationTest {
    public static final double SIGMA = 0.02e-3;
    /** Three SMRs on the flange, in the world's true flange frame, m: a triangle 60 mm across, 95 mm out. */
    public static final double[][] SMR = {{0.060, 0, 0.095}, {-0.030, 0.052, 0.095}, {-0.030, -0.052, 0.095}};

    /** A world robot, its 36 + 36 poses, and the true points of each pose (instrument frame). */
    public record Truth(RobotDescription nominal, WorldRobot world, List<Measurement> train, List<Measurement> validate) {
        /** The world's true flange frame in the instrument frame at controller values q. */
        public Rigid flange(double[] q) {
            int[] dir = new int[q.length];
            java.util.Arrays.fill(dir, 1);
            return world.target(q, dir, Double.NaN, 0, 0).times(world.flangeToTool().inverse());
        }

        public double[] point(double[] q, double[] inFlange) { return flange(q).apply(inFlange); }
    }

    public static Truth truth(long seed) {
        RobotDescription nominal = RobotLibrary.shipped("irb2400");
        WorldCampaigns.Sim sim = WorldCampaigns.geometric(nominal, seed, false, p -> p.withPoses(36, 36).withSigma(0));
        return new Truth(nominal, sim.world(), sim.train().rows(), sim.validation().rows());
    }

    /** The campaign's file text in the long form: pose, point, q1..q6 (deg), x, y, z (mm) with noise. */
    public static String longForm(Truth t, int points, long seed) { return longForm(t, SMR, points, seed); }

    static String longForm(Truth t, double[][] smr, int points, long seed) {
        Random rng = new Random(seed);
        StringBuilder b = new StringBuilder("# robopro-measurements 1\n# robot: irb2400\n# length-unit: mm\n# angle-unit: deg\n"
                + "# frame: tracker\npose,point,q1,q2,q3,q4,q5,q6,x,y,z\n");
        for (Measurement m : t.train()) {
            for (int k = 0; k < points; k++) {
                b.append(m.poseId()).append(",SMR").append(k + 1);
                for (double q : m.q()) b.append(String.format(Locale.ROOT, ",%.12f", Math.toDegrees(q)));
                double[] p = t.point(m.q(), smr[k]);
                for (double v : p) b.append(String.format(Locale.ROOT, ",%.6f", (v + SIGMA * rng.nextGaussian()) * 1e3));
                b.append('\n');
            }
        }
        return b.toString();
    }

    static MeasurementSet read(Truth t, String text) {
        return MeasurementReader.parse("smr.csv", text, t.nominal().joints().stream().map(JointDescription::type).toList());
    }

    /** RMS over validation poses and points of the calibrated prediction minus the world's point, m. */
    static double pointErrorRms(Truth t, CalibrationResult r, int points) { return pointErrorRms(t, r, SMR, points); }

    static double pointErrorRms(Truth t, CalibrationResult r, double[][] smr, int points) {
        double s = 0;
        int n = 0;
        for (Measurement m : t.validate()) {
            Pose f = r.instrumentTbase().times(r.calibrated().flange(m.q()));
            for (int k = 0; k < points; k++) {
                double[] truth = t.point(m.q(), smr[k]);
                Vec3 pred = f.apply(r.toolPoints().get(k));
                s += Math.pow(pred.minus(new Vec3(truth[0], truth[1], truth[2])).norm(), 2);
                n++;
            }
        }
        return Math.sqrt(s / n);
    }

    /**
     * RMS error, rad, of the rotation between consecutive validation poses: angle(R_a⁻¹ R_b)
     * predicted by the calibrated model against the world's. The angle of a relative rotation does
     * not depend on how either side fixes its flange axes or its instrument frame, so it compares
     * the models' orientations without sharing any convention.
     */
    static double relativeRotationErrorRms(Truth t, CalibrationResult r) {
        double s = 0;
        int n = 0;
        List<Measurement> v = t.validate();
        for (int i = 0; i + 1 < v.size(); i++) {
            double[] qa = v.get(i).q(), qb = v.get(i + 1).q();
            Pose pa = r.calibrated().flange(qa), pb = r.calibrated().flange(qb);
            double predicted = pa.angleTo(pb);
            Rigid ta = t.flange(qa), tb = t.flange(qb);
            Rigid rel = ta.inverse().times(tb);
            double[] w = rel.quaternion();
            double trueAngle = 2 * Math.atan2(Math.sqrt(w[1] * w[1] + w[2] * w[2] + w[3] * w[3]), Math.abs(w[0]));
            s += Math.pow(predicted - trueAngle, 2);
            n++;
        }
        return Math.sqrt(s / n);
    }

    @Test
    void threeSmrs_recoverThePointsToTheNoiseFloor_andTheFlangeOrientation() {
        Truth t = truth(31);
        MeasurementSet three = read(t, longForm(t, 3, 7));
        assertEquals(36, three.size());
        assertEquals(List.of("SMR1", "SMR2", "SMR3"), three.pointNames());
        CalibrationResult r3 = Calibrator.calibrate(KinematicModel.build(t.nominal()), three, null);
        double floor = Math.sqrt(3) * SIGMA;
        double rms = r3.trainRmsM();
        // Training residuals of 108 points with ~40 parameters fitted: a little under the floor, never above it by much.
        assertTrue(rms > 0.7 * floor && rms < 1.15 * floor, "training RMS " + rms * 1e3 + " mm vs floor " + floor * 1e3);
        assertEquals(108, r3.train().size());
        assertEquals(36, CalibrationResult.poses(r3.train()));
        // Each SMR's place on the flange: the three distances between them are the world's.
        for (int a = 0; a < 3; a++)
            for (int b = a + 1; b < 3; b++) {
                double trueD = Math.sqrt(Math.pow(SMR[a][0] - SMR[b][0], 2) + Math.pow(SMR[a][1] - SMR[b][1], 2) + Math.pow(SMR[a][2] - SMR[b][2], 2));
                double d = r3.toolPoints().get(a).minus(r3.toolPoints().get(b)).norm();
                assertEquals(trueD, d, 0.02e-3, "distance SMR" + (a + 1) + "-SMR" + (b + 1));
            }
        double pointErr = pointErrorRms(t, r3, 3);
        double rotErr = relativeRotationErrorRms(t, r3);
        System.out.printf(Locale.ROOT, "3 SMRs: train RMS %.4f mm (floor %.4f), validation point error vs truth %.4f mm, "
                + "relative rotation error %.5f deg, fixed %s%n", rms * 1e3, floor * 1e3, pointErr * 1e3, Math.toDegrees(rotErr), fixedNames(r3));
        assertTrue(pointErr < 0.5 * floor, "validation point error vs truth " + pointErr * 1e3 + " mm");
        // Better than one pose's own orientation noise (σ over the SMRs' ~100 mm spacing).
        assertTrue(rotErr < SIGMA / 0.1, "relative rotation error " + Math.toDegrees(rotErr) + " deg");
    }

    /** The common set-up that fails with one point: SMR 1 nearly on the joint-6 axis (1.2 mm off), two more 60 mm out. */
    static final double[][] NEAR_AXIS = {{0.0012, 0, 0.095}, {-0.030, 0.052, 0.095}, {0.060, 0, 0.095}};

    @Test
    void threeSmrs_identifyTheWristThatOneNearTheAxisCannot() {
        Truth t = truth(32);
        KinematicModel nominal = KinematicModel.build(t.nominal());
        MeasurementSet one = read(t, longForm(t, NEAR_AXIS, 1, 8)), three = read(t, longForm(t, NEAR_AXIS, 3, 8));
        CalibrationResult r1 = Calibrator.calibrate(nominal, one, null);
        CalibrationResult r3 = Calibrator.calibrate(KinematicModel.build(t.nominal()), three, null);
        List<Trust.Concern> c1 = Trust.assess(r1, one), c3 = Trust.assess(r3, three);
        double rot1 = relativeRotationErrorRms(t, r1), rot3 = relativeRotationErrorRms(t, r3);
        System.out.printf(Locale.ROOT, "near-axis SMR: concerns with 1 point %s, with 3 %s; relative rotation error 1 point %.5f deg, "
                + "3 points %.5f deg; point error vs truth 1 point %.4f mm, 3 points %.4f mm%n",
                c1.stream().map(Trust.Concern::parameter).toList(), c3.stream().map(Trust.Concern::parameter).toList(),
                Math.toDegrees(rot1), Math.toDegrees(rot3), pointErrorRms(t, r1, NEAR_AXIS, 1) * 1e3, pointErrorRms(t, r3, NEAR_AXIS, 3) * 1e3);
        // One point near the axis: the wrist offsets are not determined, and the tool says so.
        assertTrue(c1.stream().anyMatch(c -> c.parameter().startsWith("j5.") || c.parameter().startsWith("j6.")),
                "wrist concerns with one near-axis point: " + c1);
        assertTrue(c1.stream().anyMatch(c -> c.advice().contains("off the joint-6 axis")), "advice: " + c1);
        // Three points (the same one and two more): every parameter determined.
        assertTrue(c3.isEmpty(), "no concerns with three points: " + c3);
        // The single point is fitted well (that is all it sees) but the flange's rotation is not.
        assertTrue(rot3 < 0.3 * rot1, "three points predict the flange rotation better than one: " + rot3 + " vs " + rot1);
    }

    @Test
    void oneKnockedReflector_flagsItsPose_andDropsAllItsPoints() {
        Truth t = truth(36);
        String id = t.train().get(9).poseId();
        StringBuilder text = new StringBuilder();
        for (String line : longForm(t, 3, 10).split("\n")) {
            String[] v = line.split(",", -1);
            if (v.length > 2 && v[0].equals(id) && v[1].equals("SMR2")) {
                v[8] = String.format(Locale.ROOT, "%.6f", Double.parseDouble(v[8]) + 1.5); // 1.5 mm in x
                line = String.join(",", v);
            }
            text.append(line).append('\n');
        }
        CalibrationResult r = Calibrator.calibrate(KinematicModel.build(t.nominal()), read(t, text.toString()), null);
        assertEquals(List.of(id), r.outliers().stream().map(CalibrationResult.Outlier::poseId).toList());
        assertTrue(r.outliers().get(0).reason().startsWith("largest point residual"), r.outliers().get(0).reason());
        assertEquals(3, r.train().stream().filter(CalibrationResult.PoseError::outlier).count(), "all three points of the pose set aside");
        assertTrue(r.trainRmsM() < 1.15 * Math.sqrt(3) * SIGMA, "the rest fits to the floor: " + r.trainRmsM() * 1e3 + " mm");
    }

    public static List<String> fixedNames(CalibrationResult r) {
        List<String> out = new ArrayList<>();
        for (CalibrationResult.ParameterEstimate p : r.parameters()) if (p.fixed()) out.add(p.name());
        return out;
    }
}
