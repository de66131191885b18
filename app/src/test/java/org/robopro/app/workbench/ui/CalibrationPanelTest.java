package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robopro.app.benchmark.DiagnosisBenchmark;
import org.robopro.calibration.diagnosis.Diagnoser;
import org.robopro.calibration.diagnosis.Diagnosis;
import org.robopro.calibration.diagnosis.Effect;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Scenario;

class CalibrationPanelTest {
    @Test
    void diagnosisReport_backlashCampaign_namesJointParameterInDegreesAndRms() {
        var c = DiagnosisBenchmark.read(Scenario.named("lost motion j1, directions recorded").trial(5));
        Diagnosis d = Diagnoser.diagnose(RobotLibrary.shipped("irb2000"), c.train(), c.validate());
        assertEquals(1, d.effects().size(), "the concealed lost motion is the one effect");
        String text = CalibrationPanel.diagnosisReport(d);
        Diagnosis.Finding f = d.effects().get(0);
        assertTrue(text.contains("Backlash (lost motion, the output lags the motor) on joint 1"), text);
        // The parameter is shown in degrees, converted from the finding's radians.
        String b = String.format(Locale.ROOT, "b = %.4f ± %.4f deg", Math.toDegrees(f.values()[0]), Math.toDegrees(f.sigmas()[0]));
        assertTrue(text.contains(b), "expected '" + b + "' in\n" + text);
        String rms = String.format(Locale.ROOT, "RMS: training %.4f -> %.4f mm, validation %.4f -> %.4f mm", d.geometricTrainRmsM() * 1e3,
                f.trainRmsM() * 1e3, d.geometricValidateRmsM() * 1e3, f.validateRmsM() * 1e3);
        assertTrue(text.contains(rms), "expected '" + rms + "' in\n" + text);
        assertTrue(text.contains("Outliers: none."), text);
        assertTrue(text.contains("What to record next"), text);
    }

    /** A world campaign read again by another instrument, parsed as a user's file. */
    private static org.robopro.calibration.measurement.MeasurementSet read(String text) {
        return org.robopro.calibration.measurement.MeasurementReader.parse("other.csv", text,
                RobotLibrary.shipped("irb2000").joints().stream().map(j -> j.type()).toList());
    }

    @Test
    void words_severalPointsAndDistances_countPointsAndDistancesNotPoses() {
        var robot = RobotLibrary.shipped("irb2000");
        Scenario.Trial t = Scenario.named("null irb2000").trial(7, p -> p.withPoses(60, 0));
        var smr = read(org.robopro.world.Readings.points(t.world(), robot, t.campaign(),
                new double[][] {{0.06, 0, 0.095}, {-0.03, 0.052, 0.095}, {-0.03, -0.052, 0.095}}, 7));
        Diagnosis d = Diagnoser.diagnose(robot, smr, null);
        assertTrue(CalibrationPanel.rmsLines(d.geometric()).contains("(180 points on 60 poses)"), CalibrationPanel.rmsLines(d.geometric()));
        String text = CalibrationPanel.diagnosisReport(d);
        assertTrue(text.contains("over the measured points of the training poses")
                && text.contains(String.format(Locale.ROOT, "Noise floor about %.4f mm (sigma %.4f mm per axis)", Math.sqrt(3) * d.sigmaM() * 1e3,
                d.sigmaM() * 1e3)), text);

        var wire = read(org.robopro.world.Readings.distances(t.world(), robot, t.campaign(), new double[] {1.3, -0.4, 0.05}, true, 7));
        Diagnosis w = Diagnoser.diagnose(robot, wire, null);
        assertTrue(CalibrationPanel.rmsLines(w.geometric()).contains("(60 distances)"), CalibrationPanel.rmsLines(w.geometric()));
        String wt = CalibrationPanel.diagnosisReport(w);
        assertTrue(wt.contains("over the distances of the training poses")
                && wt.contains(String.format(Locale.ROOT, "Noise floor about %.4f mm (sigma %.4f mm per distance)", w.sigmaM() * 1e3,
                w.sigmaM() * 1e3)), wt);
    }

    @Test
    void parameters_complianceScaleThermal_unitsAnEngineerReads() {
        assertEquals("c = 1.00e-06 ± 1.0e-08 rad/(N·m) (stiffness 1.00e+06 N·m/rad)",
                CalibrationPanel.parameters(Effect.compliance(1, null), new double[] {1e-6}, new double[] {1e-8}));
        assertEquals("eps = 200.0 ± 3.0 ppm", CalibrationPanel.parameters(Effect.scale(0), new double[] {2e-4}, new double[] {3e-6}));
        assertEquals("alpha = 11.50 ± 0.20 µm/(m·K)",
                CalibrationPanel.parameters(Effect.thermal(20), new double[] {11.5e-6}, new double[] {0.2e-6}));
    }
}
