package org.robopro.calibration.identification;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.report.CalibrationReport;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.JointDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Readings;
import org.robopro.world.Rigid;
import org.robopro.world.Scenario;
import org.robopro.world.WorldRobot;

/**
 * Distances between pairs of poses (a length artefact or a ballbar probed by the robot): the
 * length between the measured point's places at consecutive poses of a campaign on a robot drawn
 * by the independent world simulator (org.robopro.world), read by the product's reader. Judged on
 * what such lengths can show: lengths between held-out pairs against the world's noise-free ones.
 */
class PairCalibrationTest {
    static final double SIGMA = 0.02e-3;

    @Test
    void pairs_calibrateTheArmsShape_andSayTheBasePlacementIsNotSeen() {
        RobotDescription nominal = RobotLibrary.shipped("irb2000");
        Scenario.Trial t = Scenario.named("null irb2000").trial(21, p -> p.withPoses(200, 100).withSigma(SIGMA));
        MeasurementSet all = MeasurementReader.parse("bar.csv", Readings.pairs(t.world(), nominal, t.campaign(), 21),
                nominal.joints().stream().map(JointDescription::type).toList());
        MeasurementSet train = all.split(Measurement.Split.TRAIN), val = all.split(Measurement.Split.VALIDATE);
        assertTrue(train.isPairs() && train.size() > 150, "pairs " + train.size());
        KinematicModel model = KinematicModel.build(nominal);
        CalibrationResult r = Calibrator.calibrate(model, train, val, Calibrator.Options.defaults());
        assertTrue(r.distance() && r.pairs() && r.anchor() == null);
        // held-out lengths: to the noise (one number per pair: σ is the floor)
        assertTrue(r.validateRmsM() < 1.3 * SIGMA, "validation length RMS " + r.validateRmsM() * 1e3 + " mm");
        assertTrue(r.nominalValidateRmsM() > 10 * r.validateRmsM(), "nominal " + r.nominalValidateRmsM() * 1e3 + " mm");
        // against the world's noise-free lengths, over the held-out pairs
        WorldRobot w = t.world();
        int[] up = {1, 1, 1, 1, 1, 1};
        double s = 0;
        for (Measurement m : val.rows()) {
            double truth = Rigid.norm(Rigid.minus(w.target(m.q(), up, Double.NaN, 0, 0).p(), w.target(m.fromQ(), up, Double.NaN, 0, 0).p()));
            var tool = r.flangeTtool();
            double pred = r.calibrated().flange(m.q()).times(tool).position().minus(r.calibrated().flange(m.fromQ()).times(tool).position()).norm();
            s += (pred - truth) * (pred - truth);
        }
        double rms = Math.sqrt(s / val.size());
        assertTrue(rms < SIGMA, "held-out length error against the world's truth " + rms * 1e3 + " mm");
        // what cannot be seen: the robot's placement, joint 1's zero among it
        String words = CalibrationReport.distanceWords(r);
        assertTrue(words.startsWith("distances between pairs of poses") && words.contains("j1.offset"), words);
        List<String> warnings = CalibrationReport.warnings(r, train, val);
        assertTrue(warnings.contains(words), warnings.toString());

        // validation lengths to an anchor do not check lengths between poses: refused in words, naming the file
        MeasurementSet wire = MeasurementReader.parse("wire.csv", Readings.distances(t.world(), nominal, t.campaign(),
                new double[] {1.3, -0.4, 0.05}, false, 21), nominal.joints().stream().map(JointDescription::type).toList());
        var e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> Calibrator.calibrate(model, train, wire, Calibrator.Options.defaults()));
        assertTrue(e.getMessage().startsWith("wire.csv") && e.getMessage().contains("distances between pairs of poses"), e.getMessage());
    }
}
