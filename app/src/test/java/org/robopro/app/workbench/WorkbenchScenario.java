package org.robopro.app.workbench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.atomic.AtomicReference;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.ui.WorkbenchWindow;
import org.robopro.app.workbench.model.ProgramRun;
import org.robopro.app.workbench.model.Target;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;

/**
 * Drives the workbench the way a user does, through the window's panels and actions: load the
 * cell, jog by joints and in Cartesian, teach three targets, build a path, check it, export
 * RAPID, save and reopen, try a damaged project. Runs in its own JVM (the X display must be
 * set before AWT starts); writes what happened to results.properties and screenshots into the
 * output folder for {@link WorkbenchScenarioTest} to assert on.
 */
public final class WorkbenchScenario {
    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Files.createDirectories(out);
        Properties r = new Properties();
        WorkbenchWindow win = WorkbenchWindow.open(WorkbenchWindow.Options.defaults().withSize(1280, 720));
        try {
            run(win, out, r);
            r.setProperty("status", "done");
        } catch (Throwable t) {
            r.setProperty("status", "failed: " + t);
            t.printStackTrace();
        } finally {
            try (var w = Files.newBufferedWriter(out.resolve("results.properties"))) {
                r.store(w, "workbench scenario");
            }
            win.close();
        }
        System.exit(0);
    }

    /** Records what is clipped in the window now (LayoutCheck), one entry per component. */
    static void clipped(java.awt.Container frame, Properties r, String key) {
        WorkbenchWindow.onEdt(() -> {
            frame.validate();
            r.setProperty(key, String.join("; ", org.robopro.app.workbench.ui.LayoutCheck.clipped(frame)));
        });
    }

    private static String fmt(double[] q) {
        StringBuilder sb = new StringBuilder();
        for (double v : q) sb.append(String.format(Locale.ROOT, "%.6f ", Math.toDegrees(v)));
        return sb.toString().trim();
    }

    /**
     * Screenshot {@code name}.png, and the program table's Check column as it shows in it
     * ("table.NAME": rows joined by " | "), read on the Swing thread right after the picture.
     */
    static void shot(WorkbenchWindow win, Path out, String name, Properties r) throws Exception {
        win.screenshot(out.resolve(name + ".png"));
        WorkbenchWindow.onEdt(() -> {
            List<String> shown = win.frame().programPanel().checkColumn();
            r.setProperty("table." + name, String.join(" | ", shown));
            // The table shows the last check of the program it lists (not an earlier program's).
            var latest = win.session().pathChecker().latest();
            List<String> stale = new ArrayList<>();
            if (latest != null && latest.program().equals(win.session().model().program()))
                for (int i = 0; i < shown.size(); i++) {
                    String want = latest.run().line(i).map(ProgramRun.Step::message).orElse("");
                    if (!shown.get(i).endsWith(want)) stale.add("row " + (i + 1) + " shows '" + shown.get(i) + "', the check says '" + want + "'");
                }
            r.setProperty("stale." + name, String.join("; ", stale));
        });
    }

    static void run(WorkbenchWindow win, Path out, Properties r) throws Exception {
        var wb = win.session();
        var frame = win.frame();
        r.setProperty("firstFrameSeconds", String.valueOf(win.secondsToFirstFrame()));
        r.setProperty("objects", String.valueOf(wb.model().objects().size()));
        shot(win, out, "01-cell", r);
        clipped(frame, r, "clippedMain");

        // Jog by joints through the spinners, then in Cartesian through the jog buttons.
        r.setProperty("q0", fmt(wb.model().q()));
        WorkbenchWindow.onEdt(() -> {
            frame.jogPanel().setJointDegrees(0, 10);
            frame.jogPanel().setJointDegrees(1, 30);
        });
        r.setProperty("qJointJog", fmt(wb.model().q()));
        Pose before = wb.model().worldTtcp();
        AtomicReference<Boolean> ok = new AtomicReference<>(true);
        WorkbenchWindow.onEdt(() -> {
            frame.jogPanel().setJogFrame(WorkbenchSession.JogFrame.WORLD);
            for (int i = 0; i < 5; i++) ok.set(ok.get() & frame.jogPanel().stepCartesian(2, -1)); // 5 x 10 mm down
        });
        Pose after = wb.model().worldTtcp();
        r.setProperty("cartesianJogOk", ok.get().toString());
        r.setProperty("cartesianDz", String.valueOf(after.z() - before.z()));
        r.setProperty("cartesianDxy", String.valueOf(Math.hypot(after.x() - before.x(), after.y() - before.y())));
        r.setProperty("cartesianAngle", String.valueOf(before.angleTo(after)));

        // Teach three targets (Teach action), moving between them with Cartesian jogs.
        WorkbenchWindow.onEdt(() -> frame.action("teach").actionPerformed(null));
        WorkbenchWindow.onEdt(() -> {
            frame.jogPanel().setJogFrame(WorkbenchSession.JogFrame.WORLD);
            for (int i = 0; i < 15; i++) frame.jogPanel().stepCartesian(1, 1); // +150 mm in y
            frame.action("teach").actionPerformed(null);
            frame.jogPanel().setJogFrame(WorkbenchSession.JogFrame.TOOL);
            for (int i = 0; i < 10; i++) frame.jogPanel().stepCartesian(0, 1); // 100 mm along tool x
            frame.action("teach").actionPerformed(null);
        });
        r.setProperty("targets", String.join(",", wb.model().targets().stream().map(Target::name).toList()));

        // Build a path: MoveJ to the first, MoveL to the others and back.
        WorkbenchWindow.onEdt(() -> {
            for (String t : new String[] {"p10", "p20", "p30", "p10"}) {
                wb.model().select("target:" + t);
                frame.action(t.equals("p10") && wb.model().program().isEmpty() ? "add-movej" : "add-movel").actionPerformed(null);
            }
        });
        r.setProperty("program", String.join(";", wb.model().program().stream().map(Instruction::toString).toList()));
        AtomicReference<ProgramRun> plan = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> plan.set(frame.programPanel().check()));
        r.setProperty("checkOk", String.valueOf(plan.get().ok()));
        r.setProperty("duration", String.valueOf(plan.get().duration()));

        // An unreachable target is marked red and fails the check.
        Pose cur = wb.model().worldTtcp();
        Pose orientation = Pose.translation(cur.position().times(-1)).times(cur);
        Target far = new Target("p99", Pose.translation(3.2, 0, 1.0).times(orientation), wb.model().q(),
                wb.model().kinematics().confOf(wb.model().q()));
        WorkbenchWindow.onEdt(() -> {
            wb.model().putTarget(far);
            wb.model().select("target:p99");
            frame.action("add-movel").actionPerformed(null);
            plan.set(frame.programPanel().check());
        });
        r.setProperty("checkWithFarOk", String.valueOf(plan.get().ok()));
        r.setProperty("farProblem", plan.get().steps().get(4).problems().stream()
                .filter(p -> p.severity() == org.robopro.programs.check.Problem.Severity.ERROR)
                .map(p -> p.kind() + " " + p.target()).findFirst().orElse(""));
        r.setProperty("badTargets", String.join(",", new java.util.TreeSet<>(plan.get().badTargets())));
        r.setProperty("farStatus", wb.model().status(far).name());
        WorkbenchWindow.onEdt(() -> {
            frame.programPanel().showTime(plan.get().duration() * 0.4);
            wb.model().setShowFrames(true);
        });
        shot(win, out, "02-path", r);
        WorkbenchWindow.onEdt(() -> {
            var p = new java.util.ArrayList<>(wb.model().program());
            p.remove(p.size() - 1);
            wb.model().setProgram(p);
            wb.model().removeTarget("p99");
            wb.model().setShowFrames(false);
            wb.model().select("object:web_plate");
        });

        // Export RAPID (refuses to overwrite an existing file unless asked).
        Path mod = out.resolve("Weld.mod");
        Files.deleteIfExists(mod);
        wb.exportRapid(mod, false);
        r.setProperty("rapidFile", mod.toString());
        try {
            wb.exportRapid(mod, false);
            r.setProperty("rapidOverwriteRefused", "false");
        } catch (IOException e) {
            r.setProperty("rapidOverwriteRefused", "true");
        }

        // Import RAPID: the exported module comes back as the same program; a broken file is
        // reported with its line and column and changes nothing.
        String programBefore = String.join(";", wb.model().program().stream().map(Instruction::toString).toList());
        AtomicReference<Boolean> imported = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> imported.set(frame.importRapid(mod)));
        r.setProperty("importOk", String.valueOf(imported.get()));
        r.setProperty("importSameProgram", String.valueOf(programBefore.equals(
                String.join(";", wb.model().program().stream().map(Instruction::toString).toList()))));
        r.setProperty("importTargets", String.join(",", wb.model().targets().stream().map(Target::name).toList()));
        // What the program table says about the imported program once its check is in (the same
        // wait a screenshot makes): each target taught at the robot's pose is reachable in its own configuration.
        wb.awaitPathCheck();
        WorkbenchWindow.onEdt(() -> r.setProperty("importCheck", String.join(" | ", frame.programPanel().checkColumn())));
        Path broken = out.resolve("Broken.mod");
        Files.writeString(broken, Files.readString(mod).replaceFirst("MoveL p20,", "MoveL p20 v500,"));
        WorkbenchWindow.onEdt(() -> imported.set(frame.importRapid(broken)));
        r.setProperty("brokenImportOk", String.valueOf(imported.get()));
        r.setProperty("brokenImportError", String.valueOf(frame.lastError()));
        r.setProperty("afterBrokenProgram", String.valueOf(wb.model().program().size()));

        // Cell layout: add and move a table, then save, reopen, and try a damaged copy.
        WorkbenchWindow.onEdt(() -> {
            frame.action("add-table").actionPerformed(null);
            String id = wb.model().selection().substring(7);
            wb.placeObject(id, 0.3, -1.6, 0, Math.toRadians(30));
        });
        r.setProperty("objectsAfterAdd", String.valueOf(wb.model().objects().size()));
        // Ctrl+Z takes the table back (one step: add and place were separate edits, so twice), Ctrl+Y redoes both.
        WorkbenchWindow.onEdt(() -> {
            r.setProperty("undoName", String.valueOf(frame.action("undo").getValue(javax.swing.Action.NAME)));
            frame.action("undo").actionPerformed(null);
            frame.action("undo").actionPerformed(null);
        });
        r.setProperty("objectsAfterUndo", String.valueOf(wb.model().objects().size()));
        WorkbenchWindow.onEdt(() -> {
            frame.action("redo").actionPerformed(null);
            frame.action("redo").actionPerformed(null);
        });
        r.setProperty("objectsAfterRedo", String.valueOf(wb.model().objects().size()));
        shot(win, out, "03-layout", r);
        Path project = out.resolve("cell.robopro.json");
        Files.deleteIfExists(project);
        wb.save(project);
        wb.openProject(project);
        r.setProperty("reopenedTargets", String.valueOf(wb.model().targets().size()));
        r.setProperty("reopenedProgram", String.valueOf(wb.model().program().size()));
        r.setProperty("reopenedObjects", String.valueOf(wb.model().objects().size()));
        String text = Files.readString(project);
        Path damaged = out.resolve("damaged.robopro.json");
        Files.writeString(damaged, text.replaceFirst("\"speed_mm_s\" : [0-9.]+", "\"speed_mm_s\" : \"fast\""));
        try {
            wb.openProject(damaged);
            r.setProperty("damaged", "opened");
        } catch (InputException e) {
            r.setProperty("damaged", e.getMessage());
            r.setProperty("damagedLine", String.valueOf(e.line()));
            r.setProperty("damagedField", e.field());
        }
        r.setProperty("afterDamagedTargets", String.valueOf(wb.model().targets().size()));
        r.setProperty("projectFile", wb.projectFile().map(Path::toString).orElse(""));
        r.setProperty("fps", String.valueOf(win.app().fps()));
        controller(win, out, r);
        calibration(win, out, r);
        diagnosis(win, out, r);
        wizard(win, out, r);
        // Escape closes a docked panel (the calibration panel here), as it would a dialog.
        WorkbenchWindow.onEdt(() -> {
            var cal = frame.openCalibration();
            frame.getRootPane().getActionMap().get("close-dock").actionPerformed(null);
            r.setProperty("escapeClosedDock", String.valueOf(!frame.isDocked(cal)));
        });
        // The same window at 1920 x 1080, with the wizard docked.
        WorkbenchWindow.onEdt(() -> { frame.sizeTo(1920, 1080); frame.openWizard(); });
        Thread.sleep(300);
        clipped(frame, r, "clippedLarge");
        shot(win, out, "09-large", r);
        WorkbenchWindow.onEdt(() -> { frame.closeDock(frame.openWizard()); frame.sizeTo(1280, 720); });
    }

    /**
     * Calibration panel: a simulated campaign (robopro simulate), a cancelled run, a full run in
     * the background, RMS before/after and effects shown, the calibrated model applied so the
     * RAPID export is compensated.
     */
    static void calibration(WorkbenchWindow win, Path out, Properties r) throws Exception {
        var wb = win.session();
        var frame = win.frame();
        Path sim = out.resolve("campaign");
        // The campaign of a robot drawn by the independent world simulator (60 poses, sigma 0.02 mm).
        var irb = org.robopro.models.RobotLibrary.shipped("irb2000");
        var worldRobot = org.robopro.world.Scenario.baseRobot(irb, new java.util.Random(11), 1e-3, Math.toRadians(0.1));
        java.nio.file.Files.createDirectories(sim);
        java.nio.file.Files.writeString(sim.resolve("measurements.csv"), org.robopro.world.Campaign.run(worldRobot, irb,
                org.robopro.world.Campaign.Plan.defaults(11).withPoses(60, 0).withDirColumns(false).withConditionColumns(false)).text());
        AtomicReference<org.robopro.app.workbench.ui.CalibrationPanel> panel = new AtomicReference<>();
        AtomicReference<Boolean> ok = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> {
            panel.set(frame.openCalibration());
            ok.set(panel.get().loadMeasurements(sim.resolve("measurements.csv")));
        });
        var p = panel.get();
        r.setProperty("calLoaded", String.valueOf(ok.get()));
        AtomicReference<java.util.concurrent.CompletableFuture<?>> f = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> { f.set(p.start()); p.cancel(); });
        try {
            f.get().get(60, java.util.concurrent.TimeUnit.SECONDS);
            r.setProperty("calCancelled", "finished before the cancel was seen");
        } catch (java.util.concurrent.CancellationException e) { // CompletableFuture.get rethrows it as is
            r.setProperty("calCancelled", e.getClass().getSimpleName());
        } catch (java.util.concurrent.ExecutionException e) {
            r.setProperty("calCancelled", e.getCause().getClass().getSimpleName());
        }
        Thread.sleep(100);
        r.setProperty("calStateAfterCancel", p.state());
        WorkbenchWindow.onEdt(() -> f.set(p.start()));
        f.get().get(120, java.util.concurrent.TimeUnit.SECONDS);
        Thread.sleep(200);
        WorkbenchWindow.onEdt(() -> {
            r.setProperty("calState", p.state());
            r.setProperty("calRms", p.rmsText());
            r.setProperty("calEffects", p.effectsText());
            r.setProperty("calProgress", String.valueOf(p.progressValue()));
        });
        r.setProperty("calNominalRmsMm", String.valueOf(p.result().nominalTrainRmsM() * 1e3));
        r.setProperty("calRmsMm", String.valueOf(p.result().trainRmsM() * 1e3));
        r.setProperty("calValidateRmsMm", String.valueOf(p.result().validateRmsM() * 1e3));
        // The same file through robopro calibrate (the workbench holds out every 5th pose without a set column).
        Path cli = out.resolve("calibration-cli");
        new picocli.CommandLine(new org.robopro.app.cli.RoboproCommand()).execute("calibrate", "--robot", "irb2000",
                "--measurements", sim.resolve("measurements.csv").toString(), "--holdout", "0.2", "--out", cli.toString(), "--force");
        r.setProperty("calSummarySameAsCli", String.valueOf(Files.readString(cli.resolve("summary.json"))
                .equals(wb.lastCalibration().orElseThrow().summaryJson())));
        // The figures the panel shows are the CLI's: training and validation RMS as summary.json has them.
        var cliSummary = new com.fasterxml.jackson.databind.ObjectMapper().readTree(cli.resolve("summary.json").toFile());
        r.setProperty("calCliFigures", String.format(Locale.ROOT, "Training RMS %.4f mm → %.4f mm|Validation RMS %.4f mm → %.4f mm",
                cliSummary.get("nominal_train_rms_mm").asDouble(), cliSummary.get("train_rms_mm").asDouble(),
                cliSummary.get("nominal_validate_rms_mm").asDouble(), cliSummary.get("validate_rms_mm").asDouble()));
        shot(win, out, "07-calibration", r);
        clipped(frame, r, "clippedCalibration");
        Path nominalMod = out.resolve("Nominal.mod"), compensatedMod = out.resolve("Compensated.mod");
        Files.deleteIfExists(nominalMod);
        Files.deleteIfExists(compensatedMod);
        wb.exportRapid(nominalMod, false);
        Path calFile = out.resolve("irb2000-calibrated.robot.json");
        Files.deleteIfExists(calFile);
        WorkbenchWindow.onEdt(() -> ok.set(p.apply(calFile, () -> false)));
        r.setProperty("calApplied", String.valueOf(ok.get()));
        r.setProperty("calReference", String.valueOf(wb.model().calibrationReference()));
        wb.exportRapid(compensatedMod, false);
        r.setProperty("compensatedDiffers", String.valueOf(!Files.readString(nominalMod).replace("Nominal", "X")
                .equals(Files.readString(compensatedMod).replace("Compensated", "X"))));
        r.setProperty("compensationLog", String.join("\n", wb.log().stream().filter(l -> l.startsWith("Compensated")).toList()));
        WorkbenchWindow.onEdt(() -> frame.closeDock(p));
        wb.clearCalibration();
    }

    /**
     * Diagnosis in the calibration panel: a campaign of the independent world simulator (an
     * IRB-2000 with lost motion on joint 1, approach directions recorded, written as a measurement
     * file with a train/validate set column), Diagnose in the background, the finding shown in
     * words, the extended model applied so the RAPID export is compensated with the Compensator on it.
     */
    static void diagnosis(WorkbenchWindow win, Path out, Properties r) throws Exception {
        var wb = win.session();
        var frame = win.frame();
        var trial = org.robopro.world.Scenario.named("lost motion j1, directions recorded").trial(5);
        Path file = out.resolve("backlash-campaign.csv");
        Files.writeString(file, trial.campaign().text());
        AtomicReference<org.robopro.app.workbench.ui.CalibrationPanel> panel = new AtomicReference<>();
        AtomicReference<Boolean> ok = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> {
            panel.set(frame.openCalibration());
            ok.set(panel.get().loadMeasurements(file));
        });
        var p = panel.get();
        r.setProperty("diagLoaded", String.valueOf(ok.get()));
        AtomicReference<java.util.concurrent.CompletableFuture<?>> f = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> { f.set(p.startDiagnosis()); p.cancel(); });
        try {
            f.get().get(60, java.util.concurrent.TimeUnit.SECONDS);
            r.setProperty("diagCancelled", "finished before the cancel was seen");
        } catch (java.util.concurrent.CancellationException e) {
            r.setProperty("diagCancelled", e.getClass().getSimpleName());
        } catch (java.util.concurrent.ExecutionException e) {
            r.setProperty("diagCancelled", e.getCause().getClass().getSimpleName());
        }
        WorkbenchWindow.onEdt(() -> f.set(p.startDiagnosis()));
        f.get().get(180, java.util.concurrent.TimeUnit.SECONDS);
        var d = p.diagnosis();
        WorkbenchWindow.onEdt(() -> {
            r.setProperty("diagState", p.state());
            r.setProperty("diagFindings", p.findingsText());
            r.setProperty("diagProgress", String.valueOf(p.progressValue()));
        });
        r.setProperty("diagEffects", String.join(",", d.effects().stream().map(x -> x.effect().label()).toList()));
        r.setProperty("diagGeometricValidateMm", String.valueOf(d.geometricValidateRmsM() * 1e3));
        r.setProperty("diagFinalValidateMm", String.valueOf(d.finalValidateRmsM() * 1e3));
        r.setProperty("diagFloorMm", String.valueOf(Math.sqrt(3) * d.sigmaM() * 1e3));
        shot(win, out, "08-diagnosis", r);
        clipped(frame, r, "clippedDiagnosis");
        Path nominalMod = out.resolve("NominalD.mod"), compensatedMod = out.resolve("Extended.mod");
        Files.deleteIfExists(nominalMod);
        Files.deleteIfExists(compensatedMod);
        wb.exportRapid(nominalMod, false);
        Path extFile = out.resolve("irb2000-extended.robot.json");
        Files.deleteIfExists(extFile);
        WorkbenchWindow.onEdt(() -> ok.set(p.apply(extFile, () -> false)));
        r.setProperty("diagApplied", String.valueOf(ok.get()));
        r.setProperty("diagExtendedEffects", String.valueOf(wb.extendedModel().map(x -> x.terms().size()).orElse(0)));
        r.setProperty("diagFileHasEffects", String.valueOf(org.robopro.models.RobotLibrary.load(extFile.toString()).effects().size()));
        wb.exportRapid(compensatedMod, false);
        r.setProperty("diagCompensatedDiffers", String.valueOf(!Files.readString(nominalMod).replace("NominalD", "X")
                .equals(Files.readString(compensatedMod).replace("Extended", "X"))));
        r.setProperty("diagCompensationLog", String.join("\n", wb.log().stream().filter(l -> l.startsWith("Compensated")).toList()));
        WorkbenchWindow.onEdt(() -> frame.closeDock(p));
        wb.clearCalibration();
    }

    /**
     * Controller menu against the simulated controller: connect (starts controller-sim),
     * download, run, read the real robot's joints (ghost), upload, disconnect.
     */
    static void controller(WorkbenchWindow win, Path out, Properties r) throws Exception {
        var wb = win.session();
        var frame = win.frame();
        r.setProperty("downloadEnabledBefore", String.valueOf(frame.action("download").isEnabled()));
        var s = wb.connectController(null).get(60, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("controllerRobot", s.robotName());
        Thread.sleep(200); // the enable/disable runs on the Swing thread
        WorkbenchWindow.onEdt(() -> r.setProperty("downloadEnabledAfter", String.valueOf(frame.action("download").isEnabled())));
        var info = wb.downloadProgram().get(30, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("downloadedName", info.name());
        r.setProperty("downloadedLength", String.valueOf(info.length()));
        var st = wb.runProgram().get(60, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("runState", st.state().name());
        double[] ghost = wb.model().ghostQ();
        Pose last = wb.model().target(wb.model().program().get(wb.model().program().size() - 1).target()).orElseThrow().worldTtcp();
        r.setProperty("ghostToLastTargetMm", String.valueOf(1000 * wb.model().worldTtcp(ghost).distanceTo(last)));
        WorkbenchWindow.onEdt(() -> {
            frame.jogPanel().setJointDegrees(0, -35);
            frame.jogPanel().setJointDegrees(1, 0);
        });
        shot(win, out, "06-controller", r);
        clipped(frame, r, "clippedController");
        var imp = wb.uploadProgram(info.name()).get(30, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("uploadedInstructions", String.valueOf(imp.program().size()));
        r.setProperty("programAfterUpload", String.valueOf(wb.model().program().size()));
        r.setProperty("controllerLog", String.join("\n", wb.log().stream().filter(l -> l.startsWith("Controller:")).toList()));

        // A program with MoveC: checked, downloaded and run on the simulated controller, which ends at the arc's end.
        WorkbenchWindow.onEdt(() -> wb.model().setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 10),
                new Instruction(Instruction.Type.MOVEC, "p30", 200, 0, "p20"))));
        r.setProperty("moveCCheckOk", String.valueOf(wb.checkProgram().ok()));
        wb.downloadProgram().get(30, java.util.concurrent.TimeUnit.SECONDS);
        var stc = wb.runProgram().get(60, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("moveCRunState", stc.state().name() + " " + stc);
        Pose p30 = wb.model().target("p30").orElseThrow().worldTtcp();
        r.setProperty("moveCGhostToP30Mm", String.valueOf(1000 * wb.model().worldTtcp(wb.model().ghostQ()).distanceTo(p30)));
        // Upload lets the user choose the PROC: a module whose second procedure calls main twice.
        String text = org.robopro.programs.RapidWriter.export(
                org.robopro.app.workbench.model.ProgramModule.toRapid(wb.model(), "Twice")).text();
        text = text.substring(0, text.lastIndexOf("ENDMODULE")) + "  PROC twice()\n    main;\n    main;\n  ENDPROC\nENDMODULE\n";
        wb.controller().orElseThrow().download("Twice", text).get(30, java.util.concurrent.TimeUnit.SECONDS);
        AtomicReference<List<String>> offered = new AtomicReference<>();
        var twice = wb.uploadProgram("Twice", procs -> { offered.set(procs); return "twice"; }).get(30, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("uploadOfferedProcs", String.join(",", offered.get()));
        r.setProperty("uploadTwiceProgram", String.join("|", twice.program().stream()
                .map(i -> i.type().motion() ? i.type() + " " + i.target() : "RAPID " + i.statementText()).toList()));
        shot(win, out, "10-kept-statements", r); // the program panel: two calls kept read-only
        r.setProperty("uploadTwiceMotions", String.join(";", wb.model().programRun().steps().stream()
                .map(step -> step.label().replaceAll(".*#\\d+ ", "")).toList()));
        try {
            wb.uploadProgram("Twice", procs -> null).get(30, java.util.concurrent.TimeUnit.SECONDS);
            r.setProperty("uploadCancelled", "no");
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.CancellationException e) {
            r.setProperty("uploadCancelled", String.valueOf(wb.model().program().size()));
        }
        WorkbenchWindow.onEdt(() -> wb.model().undo()); // the upload: program and its module back as they were
        wb.disconnectController().get(10, java.util.concurrent.TimeUnit.SECONDS);
        r.setProperty("ghostAfterDisconnect", String.valueOf(wb.model().ghostQ() != null));
    }

    /**
     * The robot model wizard: start from the IRB-2000, break and fix a joint axis (the error is
     * shown, the model rebuilt), move joint 1, save the robot file (an existing file only after
     * confirmation) and use the new robot in the cell.
     */
    static void wizard(WorkbenchWindow win, Path out, Properties r) throws Exception {
        var wb = win.session();
        var frame = win.frame();
        AtomicReference<org.robopro.app.workbench.ui.RobotWizard> w = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> {
            frame.action("robot-wizard").actionPerformed(null);
            w.set(frame.openWizard());
            w.get().startFrom("irb2000");
            w.get().setRobotName("irb2000_long", "IRB 2000, longer upper arm");
        });
        var wiz = w.get();
        r.setProperty("wizardJoints", String.valueOf(wiz.wizardModel().jointCount()));
        r.setProperty("wizardFirstOk", String.valueOf(wiz.result().ok()));
        Pose[] first = wiz.result().framesAtZero();
        r.setProperty("wizardFlangeZ0", String.valueOf(first[first.length - 1].z()));
        WorkbenchWindow.onEdt(() -> {
            wiz.setJointCell(2, "Axis x", "0");
            wiz.setJointCell(2, "Axis y", "0");
        });
        r.setProperty("wizardBrokenError", wiz.errorText());
        r.setProperty("wizardBrokenOk", String.valueOf(wiz.result().ok()));
        WorkbenchWindow.onEdt(() -> {
            wiz.setJointCell(2, "Axis y", "1");
            // Longer upper arm: joints 3.. and the flange 200 mm higher.
            for (int j = 2; j < wiz.wizardModel().jointCount(); j++)
                wiz.setJointCell(j, "Z mm", String.valueOf(wiz.wizardModel().joint(j).pointMm()[2] + 200));
            wiz.setFlangeCell(0, 2, wiz.wizardModel().flangeOriginMm()[2] + 200);
        });
        // Ctrl+Z in the wizard's table goes through the window's one undo history (Edit > Undo):
        // the flange edit is taken back, Ctrl+Y makes it again.
        double flangeZ = wiz.wizardModel().flangeOriginMm()[2];
        WorkbenchWindow.onEdt(() -> r.setProperty("wizardUndoName", String.valueOf(frame.action("undo").getValue(javax.swing.Action.NAME))));
        WorkbenchWindow.onEdt(() -> {
            javax.swing.JTable t = wiz.jointTable();
            t.dispatchEvent(new java.awt.event.KeyEvent(t, java.awt.event.KeyEvent.KEY_PRESSED, System.currentTimeMillis(),
                    java.awt.event.InputEvent.CTRL_DOWN_MASK, java.awt.event.KeyEvent.VK_Z, java.awt.event.KeyEvent.CHAR_UNDEFINED));
            r.setProperty("wizardCtrlZFlangeDelta", String.valueOf(wiz.wizardModel().flangeOriginMm()[2] - flangeZ));
        });
        WorkbenchWindow.onEdt(() -> {
            javax.swing.JTable t = wiz.jointTable();
            t.dispatchEvent(new java.awt.event.KeyEvent(t, java.awt.event.KeyEvent.KEY_PRESSED, System.currentTimeMillis(),
                    java.awt.event.InputEvent.CTRL_DOWN_MASK, java.awt.event.KeyEvent.VK_Y, java.awt.event.KeyEvent.CHAR_UNDEFINED));
            r.setProperty("wizardCtrlYFlangeDelta", String.valueOf(wiz.wizardModel().flangeOriginMm()[2] - flangeZ));
        });
        r.setProperty("wizardFixedOk", String.valueOf(wiz.result().ok()));
        r.setProperty("wizardError", wiz.errorText());
        Pose[] frames = wiz.result().framesAtZero();
        r.setProperty("wizardFlangeZ", String.valueOf(frames[frames.length - 1].z()));
        r.setProperty("wizardPreviewFrames", String.valueOf(wb.model().preview() == null ? 0 : wb.model().preview().frames().length));
        r.setProperty("wizardReportHasTable", String.valueOf(wiz.reportText().contains("identified parameters")));
        win.app().awaitFrames(3, 10_000);
        r.setProperty("wizardPreviewDrawn", String.valueOf(win.app().previewState().frameCount()));
        r.setProperty("wizardPreviewDrums", String.valueOf(win.app().previewState().partCount("preview-joint-")));
        r.setProperty("wizardPreviewLinks", String.valueOf(win.app().previewState().partCount("preview-link-")));
        // One link between each two successive distinct points: base origin, joint points, flange.
        var pts = new java.util.ArrayList<org.robopro.models.Vec3>();
        pts.add(new org.robopro.models.Vec3(0, 0, 0));
        for (var j : wb.model().preview().robot().joints()) pts.add(j.point());
        pts.add(wb.model().preview().robot().flange().origin());
        int links = 0;
        for (int i = 1; i < pts.size(); i++) if (pts.get(i).minus(pts.get(i - 1)).norm() > 1e-6) links++;
        r.setProperty("wizardPreviewLinksExpected", String.valueOf(links));
        win.setView(org.robopro.app.workbench.scene.CameraState.View.SIDE);
        // A little from the front and above, so the drums read as cylinders along their axes.
        win.app().camera().orbit(0.55, 0.2);
        win.app().camera().focus(0.5, 0, 1.05);
        win.app().camera().zoom(0.95);
        shot(win, out, "04-wizard", r);
        clipped(frame, r, "clippedWizard");
        Path robotFile = out.resolve("irb2000_long.robot.json");
        Files.deleteIfExists(robotFile);
        AtomicReference<Boolean> saved = new AtomicReference<>();
        WorkbenchWindow.onEdt(() -> saved.set(wiz.save(robotFile, () -> false)));
        r.setProperty("wizardSaved", String.valueOf(saved.get()));
        WorkbenchWindow.onEdt(() -> saved.set(wiz.save(robotFile, () -> false)));
        r.setProperty("wizardOverwriteRefused", String.valueOf(!saved.get()));
        WorkbenchWindow.onEdt(() -> saved.set(wiz.save(robotFile, () -> true)));
        r.setProperty("wizardOverwriteConfirmed", String.valueOf(saved.get()));
        WorkbenchWindow.onEdt(() -> saved.set(wiz.useInCell(() -> false)));
        r.setProperty("wizardUsed", String.valueOf(saved.get()));
        r.setProperty("cellRobot", wb.model().robot().name());
        r.setProperty("cellRobotRef", wb.model().robotRef());
        r.setProperty("previewAfterUse", String.valueOf(wb.model().preview() != null));
        WorkbenchWindow.onEdt(() -> frame.closeDock(wiz));
        win.setView(org.robopro.app.workbench.scene.CameraState.View.ISO);
        Path project = out.resolve("long.robopro.json");
        Files.deleteIfExists(project);
        wb.save(project);
        r.setProperty("reopenedRobot", ProjectStore.read(project).robot().name());
        shot(win, out, "05-new-robot", r);
        // Edit > Undo after the wizard was closed: first Use in cell (the cell's robot back), then the
        // wizard's last edit, which opens the wizard again to show it; Redo makes both again.
        WorkbenchWindow.onEdt(() -> frame.action("undo").actionPerformed(null));
        r.setProperty("undoUseInCellRobot", wb.model().robot().name());
        WorkbenchWindow.onEdt(() -> frame.action("undo").actionPerformed(null));
        WorkbenchWindow.onEdt(() -> {
            r.setProperty("undoWizardReopened", String.valueOf(frame.isDocked(wiz)));
            r.setProperty("undoWizardFlangeZ", String.valueOf(wiz.wizardModel().flangeOriginMm()[2]));
        });
        WorkbenchWindow.onEdt(() -> frame.action("redo").actionPerformed(null));
        WorkbenchWindow.onEdt(() -> frame.action("redo").actionPerformed(null));
        WorkbenchWindow.onEdt(() -> {
            r.setProperty("redoWizardFlangeZ", String.valueOf(wiz.wizardModel().flangeOriginMm()[2]));
            r.setProperty("redoRobot", wb.model().robot().name());
            frame.closeDock(wiz);
        });
    }
}
