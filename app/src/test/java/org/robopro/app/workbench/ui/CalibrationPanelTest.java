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

    @Test
    void parameters_complianceScaleThermal_unitsAnEngineerReads() {
        assertEquals("c = 1.00e-06 ± 1.0e-08 rad/(N·m) (stiffness 1.00e+06 N·m/rad)",
                CalibrationPanel.parameters(Effect.compliance(1, null), new double[] {1e-6}, new double[] {1e-8}));
        assertEquals("eps = 200.0 ± 3.0 ppm", CalibrationPanel.parameters(Effect.scale(0), new double[] {2e-4}, new double[] {3e-6}));
        assertEquals("alpha = 11.50 ± 0.20 µm/(m·K)",
                CalibrationPanel.parameters(Effect.thermal(20), new double[] {11.5e-6}, new double[] {0.2e-6}));
    }
}
