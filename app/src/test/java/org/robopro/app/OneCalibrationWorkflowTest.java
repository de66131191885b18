package org.robopro.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.cli.CliHarness;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.calibration.Cancellation;
import org.robopro.calibration.Progress;

/**
 * The command line and the workbench session run the one calibration workflow: the same file
 * and split give byte-identical summary.json and residuals.csv (the demo's side is in DemoTest).
 */
class OneCalibrationWorkflowTest {
    @TempDir Path dir;

    @Test
    void workbenchSessionAndCli_sameCampaign_byteIdenticalSummary() throws Exception {
        CliHarness cli = new CliHarness();
        Path sim = dir.resolve("sim"), out = dir.resolve("cli");
        assertEquals(0, cli.run("simulate", "--robot", "irb2000", "--poses", "80", "--seed", "31", "--out", sim.toString()), cli.err());
        Path file = sim.resolve("measurements.csv");
        // The workbench holds out every 5th pose of a file without a set column; the command line does so with --holdout 0.2.
        assertEquals(0, cli.run("calibrate", "--robot", "irb2000", "--measurements", file.toString(), "--holdout", "0.2",
                "--out", out.toString()), cli.err());
        WorkbenchSession wb = WorkbenchSession.open(null);
        var m = wb.loadMeasurements(file);
        wb.calibrate(m, Cancellation.NONE, Progress.NONE);
        var oc = wb.lastCalibration().orElseThrow();
        assertEquals(Files.readString(out.resolve("summary.json")), oc.summaryJson());
        assertEquals(Files.readString(out.resolve("residuals.csv")), oc.residualsCsv());
    }

    /**
     * The diagnosis too: the workbench session and {@code robopro diagnose} on the same file and
     * split find the same effects with the same figures (diagnosis.json equal but for its run time).
     */
    @Test
    void workbenchSessionAndCliDiagnose_sameCampaign_sameDiagnosisJson() throws Exception {
        var trial = org.robopro.world.Scenario.named("lost motion j1, directions recorded").trial(5);
        Path file = dir.resolve("backlash.csv"), out = dir.resolve("diag");
        Files.writeString(file, trial.campaign().text());
        CliHarness cli = new CliHarness();
        assertEquals(0, cli.run("diagnose", "--robot", "irb2000", "--measurements", file.toString(), "--holdout", "0.2",
                "--out", out.toString()), cli.err());
        var mapper = new com.fasterxml.jackson.databind.ObjectMapper();
        var fromCli = (com.fasterxml.jackson.databind.node.ObjectNode) mapper.readTree(out.resolve("diagnosis.json").toFile());
        WorkbenchSession wb = WorkbenchSession.open(null);
        var d = wb.diagnose(wb.loadMeasurements(file), Cancellation.NONE, Progress.NONE);
        var ctx = new org.robopro.calibration.diagnosis.DiagnosisReport.Context(fromCli.get("measurements").asText(),
                fromCli.get("validation").isNull() ? null : fromCli.get("validation").asText(), fromCli.get("created").asText());
        var fromWorkbench = (com.fasterxml.jackson.databind.node.ObjectNode) mapper.readTree(
                org.robopro.calibration.diagnosis.DiagnosisReport.json(d, ctx));
        fromCli.remove("elapsed_ms");
        fromWorkbench.remove("elapsed_ms");
        assertEquals(1, fromCli.get("effects").size(), "the lost motion is found");
        assertEquals(fromCli.toPrettyString(), fromWorkbench.toPrettyString());
    }
}
