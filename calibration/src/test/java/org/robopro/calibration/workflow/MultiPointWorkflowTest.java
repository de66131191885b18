package org.robopro.calibration.workflow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;
import org.robopro.calibration.identification.CalibrationResult;
import org.robopro.calibration.identification.MultiPointCalibrationTest;
import org.robopro.calibration.measurement.MeasurementReader;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.measurement.MeasurementWriter;

/** The workflow on a campaign with three reflectors per pose: folds by pose, one residual row per pose and point. */
class MultiPointWorkflowTest {
    @TempDir Path dir;

    @Test
    void folds_keepEachPosesPointsTogether_andResidualsHaveAPointColumn() throws Exception {
        MultiPointCalibrationTest.Truth t = MultiPointCalibrationTest.truth(33);
        Path f = dir.resolve("smr.csv");
        Files.writeString(f, MultiPointCalibrationTest.longForm(t, 3, 9));
        CalibrationWorkflow.Campaign c = CalibrationWorkflow.load(t.nominal(), f, null, 0.25);
        assertEquals(27, c.train().size()); // poses, not points: every 4th of 36 validates with its three points
        assertEquals(9, c.validate().size());
        CalibrationWorkflow.Outcome oc = CalibrationWorkflow.run(t.nominal(), c, CalibrationWorkflow.Settings.defaults().withFolds(3, 1),
                "2026-01-01T00:00:00Z", Cancellation.NONE, Progress.NONE);
        // Every point of a pose is held out in the same fold (the fold's held-out errors come in whole poses).
        for (CalibrationWorkflow.Fold fold : oc.folds()) {
            Map<String, Integer> perPose = new HashMap<>();
            for (CalibrationResult.PoseError e : fold.result().validate()) perPose.merge(e.poseId(), 1, Integer::sum);
            for (int n : perPose.values()) assertEquals(3, n);
            for (CalibrationResult.PoseError e : fold.result().train()) assertTrue(!perPose.containsKey(e.poseId()));
        }
        String csv = oc.residualsCsv();
        List<String> lines = csv.lines().toList();
        assertTrue(lines.get(0).startsWith("pose,point,set,fold,outlier,nominal_mm,dx_mm,dy_mm,dz_mm,norm_mm"), lines.get(0));
        assertEquals(1 + 36 * 3, lines.size());
        Map<String, String> foldOfPose = new HashMap<>();
        for (String l : lines.subList(1, 1 + 27 * 3)) {
            String[] v = l.split(",", -1);
            assertTrue(v[1].startsWith("SMR"), l);
            String prev = foldOfPose.putIfAbsent(v[0], v[3]);
            if (prev != null) assertEquals(prev, v[3], "pose " + v[0] + " split across folds");
        }
        String summary = oc.summaryJson();
        assertTrue(summary.contains("\"poses_train\" : 27") || summary.contains("\"poses_train\":27"), summary.substring(0, 400));
        assertTrue(summary.contains("measured_points") && summary.contains("SMR3"), "summary names the points");
        assertTrue(oc.calibrated().provenance().get("calibration-measured-points-mm").startsWith("SMR1: "));
        assertTrue(oc.warnings().stream().noneMatch(w -> w.contains("lie on a line")), oc.warnings().toString());
        // The calibrated training RMS is per measured point: near √3 σ.
        double floor = Math.sqrt(3) * MultiPointCalibrationTest.SIGMA;
        assertTrue(oc.result().trainRmsM() < 1.2 * floor && oc.result().validateRmsM() < 1.5 * floor,
                oc.result().trainRmsM() * 1e3 + " / " + oc.result().validateRmsM() * 1e3 + " mm vs floor " + floor * 1e3);
    }

    @Test
    void writer_roundTripsTheLongForm() throws Exception {
        MultiPointCalibrationTest.Truth t = MultiPointCalibrationTest.truth(34);
        var types = t.nominal().joints().stream().map(j -> j.type()).toList();
        MeasurementSet s = MeasurementReader.parse("a.csv", MultiPointCalibrationTest.longForm(t, 3, 1), types);
        Path out = dir.resolve("b.csv");
        MeasurementWriter.write(s, types, out, false);
        MeasurementSet back = MeasurementReader.read(out, types);
        assertEquals(s.pointNames(), back.pointNames());
        for (int i = 0; i < s.size(); i++)
            for (int k = 0; k < 3; k++) assertTrue(s.rows().get(i).point(k).minus(back.rows().get(i).point(k)).norm() < 1e-9);
    }

    @Test
    void distances_residualsHaveTheDistanceError_andTheSummarySaysWhatIsNotSeen() throws Exception {
        org.robopro.calibration.identification.DistanceCalibrationTest.Truth t =
                org.robopro.calibration.identification.DistanceCalibrationTest.truth(43, 120);
        Path f = dir.resolve("wire.csv");
        Files.writeString(f, org.robopro.calibration.identification.DistanceCalibrationTest.file(t, 3, false));
        CalibrationWorkflow.Campaign c = CalibrationWorkflow.load(t.nominal(), f, null, 0.2);
        CalibrationWorkflow.Outcome oc = CalibrationWorkflow.run(t.nominal(), c, CalibrationWorkflow.Settings.defaults().withFolds(4, 2),
                "2026-01-01T00:00:00Z", Cancellation.NONE, Progress.NONE);
        List<String> lines = oc.residualsCsv().lines().toList();
        assertEquals("pose,set,fold,outlier,nominal_mm,dd_mm,norm_mm,cv_dd_mm,cv_norm_mm", lines.get(0));
        assertEquals(1 + 120, lines.size());
        for (String l : lines.subList(1, lines.size())) {
            String[] v = l.split(",", -1);
            assertEquals(Math.abs(Double.parseDouble(v[5])), Double.parseDouble(v[6]), 2e-6, l);
        }
        String summary = oc.summaryJson();
        assertTrue(summary.contains("distance_only") && summary.contains("anchor_base_mm"), "summary marks distance data");
        assertTrue(oc.warnings().stream().anyMatch(w -> w.startsWith("distance-only data: ") && w.contains("not observable")), oc.warnings().toString());
        assertTrue(oc.calibrated().provenance().get("calibration-anchor-mm").endsWith("(identified, base frame)"));
        double sigma = org.robopro.calibration.identification.DistanceCalibrationTest.SIGMA;
        assertTrue(oc.result().validateRmsM() < 1.5 * sigma, "held-out distance RMS " + oc.result().validateRmsM() * 1e3 + " mm");
    }

    @Test
    void diagnose_readsSeveralPoints_andNamesNothingOnAGeometricRobot() {
        MultiPointCalibrationTest.Truth t = MultiPointCalibrationTest.truth(35);
        var types = t.nominal().joints().stream().map(j -> j.type()).toList();
        MeasurementSet s = MeasurementReader.parse("smr.csv", MultiPointCalibrationTest.longForm(t, 3, 1), types);
        var d = org.robopro.calibration.diagnosis.Diagnoser.diagnose(t.nominal(), s, null);
        assertTrue(d.effects().isEmpty(), d.effects().toString());
        assertEquals(3, d.pointsPerPose());
        assertTrue(d.finalTrainRmsM() < 1.3 * Math.sqrt(3) * MultiPointCalibrationTest.SIGMA, "RMS over every point " + d.finalTrainRmsM());
    }

    @Test
    void validationWithOtherPoints_isRefusedInWords() throws Exception {
        MultiPointCalibrationTest.Truth t = MultiPointCalibrationTest.truth(37);
        Path a = dir.resolve("three.csv"), b = dir.resolve("two.csv");
        Files.writeString(a, MultiPointCalibrationTest.longForm(t, 3, 1));
        Files.writeString(b, MultiPointCalibrationTest.longForm(t, 2, 2));
        CalibrationWorkflow.Campaign c = CalibrationWorkflow.load(t.nominal(), a, b, null);
        var e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class, () -> CalibrationWorkflow.run(
                t.nominal(), c, CalibrationWorkflow.Settings.defaults(), "2026-01-01T00:00:00Z", Cancellation.NONE, Progress.NONE));
        assertTrue(e.getMessage().contains("two.csv: field 'point'") && e.getMessage().contains("measure points SMR1, SMR2 but the training data points SMR1, SMR2, SMR3"),
                e.getMessage());
    }

    @Test
    void twoPoints_lieOnALine_andTheWarningSaysWhatIsNotSeen() throws Exception {
        MultiPointCalibrationTest.Truth t = MultiPointCalibrationTest.truth(38);
        Path f = dir.resolve("two.csv");
        Files.writeString(f, MultiPointCalibrationTest.longForm(t, 2, 4));
        CalibrationWorkflow.Outcome oc = CalibrationWorkflow.run(t.nominal(), CalibrationWorkflow.load(t.nominal(), f, null, null),
                CalibrationWorkflow.Settings.defaults(), "2026-01-01T00:00:00Z", Cancellation.NONE, Progress.NONE);
        assertTrue(oc.warnings().stream().anyMatch(w -> w.startsWith("the 2 measured points lie on a line")
                && w.contains("rotation about that line is not seen")), oc.warnings().toString());
    }
}
