package org.robopro.calibration.workflow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementWriter;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;

class CalibrationWorkflowTest {
    @TempDir Path dir;

    static final RobotDescription IRB = RobotLibrary.shipped("irb2000");

    /** A campaign on a robot of the independent world simulator, written as a measurement file (no set column). */
    Path campaign(String name, int poses, long seed) throws Exception {
        org.robopro.world.Campaign.Result c = org.robopro.calibration.WorldCampaigns.geometric(IRB, seed, false,
                p -> p.withPoses(poses, 0).withDirColumns(false).withConditionColumns(false)).campaign();
        Path f = dir.resolve(name);
        Files.writeString(f, c.text());
        return f;
    }

    @Test
    void load_holdout_everyNthPoseValidatesAndTheSourceSaysSo() throws Exception {
        Path f = campaign("m.csv", 50, 3);
        CalibrationWorkflow.Campaign c = CalibrationWorkflow.load(IRB, f, null, 0.2);
        assertEquals(40, c.train().size());
        assertEquals(10, c.validate().size());
        for (int i = 0; i < 10; i++) assertEquals(c.all().rows().get(5 * i + 4), c.validate().rows().get(i));
        assertTrue(c.source().startsWith("m.csv (hold-out: every 5th"), c.source());
        CalibrationWorkflow.Campaign none = CalibrationWorkflow.load(IRB, f, null, null);
        assertNull(none.validate());
        assertEquals(50, none.train().size());
        assertThrows(IllegalArgumentException.class, () -> CalibrationWorkflow.load(IRB, f, null, 1.5));
    }

    @Test
    void load_setColumnWinsOverHoldout_andRobotMismatchIsAWarning() throws Exception {
        Path f = campaign("m.csv", 30, 4);
        var all = CalibrationWorkflow.load(IRB, f, null, null).all();
        List<Measurement> rows = new ArrayList<>();
        for (int i = 0; i < all.size(); i++) rows.add(all.rows().get(i).withSet(i < 6 ? Measurement.Split.VALIDATE : Measurement.Split.TRAIN));
        var meta = new java.util.LinkedHashMap<>(all.metadata());
        meta.put("robot", "irb2400");
        Path g = dir.resolve("split.csv");
        MeasurementWriter.write(new org.robopro.calibration.measurement.MeasurementSet("x", meta, all.frame(), rows),
                IRB.joints().stream().map(j -> j.type()).toList(), g, true);
        var c = CalibrationWorkflow.load(IRB, g, null, 0.2);
        assertEquals(6, c.validate().size());
        assertEquals(24, c.train().size());
        assertEquals("split.csv (set=validate)", c.source());
        assertEquals(1, c.warnings().size(), c.warnings().toString());
        assertTrue(c.warnings().get(0).contains("'irb2400'") && c.warnings().get(0).contains("'irb2000'"), c.warnings().get(0));
    }

    @Test
    void folds_sameSeedSameFolds_partitionWithSizesWithinOne() {
        int[] a = MeasurementSet.folds(103, 5, 1), b = MeasurementSet.folds(103, 5, 1), c = MeasurementSet.folds(103, 5, 2);
        assertArrayEquals(a, b);
        assertFalse(java.util.Arrays.equals(a, c), "another seed, other folds");
        int[] size = new int[5];
        for (int f : a) size[f]++;
        for (int s : size) assertTrue(s == 20 || s == 21, java.util.Arrays.toString(size));
        boolean inOrder = true;
        for (int i = 0; i < a.length; i++) inOrder &= a[i] == i % 5;
        assertFalse(inOrder, "folds are shuffled, not file order");
        assertThrows(IllegalArgumentException.class, () -> MeasurementSet.folds(3, 5, 1));
    }

    @Test
    void run_folds_everyTrainingPoseHeldOutOnce_summaryIndependentOfTheClock() throws Exception {
        Path f = campaign("m.csv", 60, 5);
        var c = CalibrationWorkflow.load(IRB, f, null, 0.2);
        var s = CalibrationWorkflow.Settings.defaults().withFolds(3, 7);
        var a = CalibrationWorkflow.run(IRB, c, s, "2026-01-01T00:00:00Z", Cancellation.NONE, Progress.NONE);
        var b = CalibrationWorkflow.run(IRB, c, s, "2027-02-02T00:00:00Z", Cancellation.NONE, Progress.NONE);
        assertEquals(a.summaryJson(), b.summaryJson(), "summary.json depends on data and settings only");
        assertNotEquals(a.reportHtml(), b.reportHtml(), "the report carries the date");
        assertEquals("2026-01-01T00:00:00Z", a.calibrated().provenance().get("calibrated-on"));
        for (String k : List.of("calibrated-from", "calibrated-nominal", "calibration-measured-point-mm", "calibration-train-rms-mm",
                "calibration-validate-rms-mm"))
            assertTrue(a.calibrated().provenance().containsKey(k), k);
        assertEquals(3, a.folds().size());
        // The per-pose error plots number the validation poses on from the training ones: the two sets do not overlap.
        String html = a.reportHtml();
        int after = html.indexOf("After: calibrated model");
        String svg = html.substring(html.lastIndexOf("<svg", after), html.indexOf("</svg>", after));
        double trainMax = Double.NEGATIVE_INFINITY, valMin = Double.POSITIVE_INFINITY;
        var circle = java.util.regex.Pattern.compile("<circle cx=\"([0-9.]+)\"[^>]*fill=\"(#[0-9a-f]+)\"").matcher(svg);
        int n = 0;
        while (circle.find()) {
            double x = Double.parseDouble(circle.group(1));
            if (circle.group(2).equals("#1f77b4")) trainMax = Math.max(trainMax, x);
            else valMin = Math.min(valMin, x);
            n++;
        }
        assertEquals(60, n, "one point per pose");
        assertTrue(valMin > trainMax, "validation points right of every training point: " + valMin + " vs " + trainMax);
        Set<String> heldOut = new HashSet<>();
        for (var fold : a.folds()) for (var e : fold.result().validate()) assertTrue(heldOut.add(e.poseId()), "once: " + e.poseId());
        Set<String> train = new HashSet<>();
        for (var m : c.train().rows()) train.add(m.poseId());
        assertEquals(train, heldOut);
        String csv = a.residualsCsv();
        assertEquals(1 + 60, csv.split("\n").length);
        for (String line : csv.split("\n")) {
            if (line.startsWith("pose,")) continue;
            String[] cells = line.split(",", -1);
            assertEquals(cells[1].equals("train"), !cells[2].isEmpty(), "training rows carry their fold: " + line);
        }
    }

    @Test
    void write_existingFileWithoutOverwrite_nothingWritten() throws Exception {
        Path f = campaign("m.csv", 40, 6);
        var oc = CalibrationWorkflow.run(IRB, CalibrationWorkflow.load(IRB, f, null, null), CalibrationWorkflow.Settings.defaults(),
                "2026-01-01T00:00:00Z", Cancellation.NONE, Progress.NONE);
        Path out = Files.createDirectories(dir.resolve("out"));
        Files.writeString(out.resolve(CalibrationWorkflow.REPORT), "mine");
        assertThrows(FileAlreadyExistsException.class, () -> oc.write(out, false));
        try (var files = Files.list(out)) {
            assertEquals(List.of(out.resolve(CalibrationWorkflow.REPORT)), files.toList(), "nothing else written, no temporary left");
        }
        assertEquals("mine", Files.readString(out.resolve(CalibrationWorkflow.REPORT)));
        oc.write(out, true);
        for (String n : List.of(CalibrationWorkflow.ROBOT_FILE, CalibrationWorkflow.SUMMARY, CalibrationWorkflow.RESIDUALS, CalibrationWorkflow.REPORT))
            assertTrue(Files.size(out.resolve(n)) > 100, n);
        assertEquals(oc.summaryJson(), Files.readString(out.resolve(CalibrationWorkflow.SUMMARY)));
    }
}
