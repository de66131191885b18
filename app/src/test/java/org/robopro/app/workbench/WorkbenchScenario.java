package org.robopro.app.workbench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.atomic.AtomicReference;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.ProgramPlan;
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
        Workbench wb = Workbench.open(Workbench.Options.defaults().withSize(1280, 720));
        try {
            run(wb, out, r);
            r.setProperty("status", "done");
        } catch (Throwable t) {
            r.setProperty("status", "failed: " + t);
            t.printStackTrace();
        } finally {
            try (var w = Files.newBufferedWriter(out.resolve("results.properties"))) {
                r.store(w, "workbench scenario");
            }
            wb.close();
        }
        System.exit(0);
    }

    private static String fmt(double[] q) {
        StringBuilder sb = new StringBuilder();
        for (double v : q) sb.append(String.format(Locale.ROOT, "%.6f ", Math.toDegrees(v)));
        return sb.toString().trim();
    }

    static void run(Workbench wb, Path out, Properties r) throws Exception {
        var frame = wb.frame();
        r.setProperty("firstFrameSeconds", String.valueOf(wb.secondsToFirstFrame()));
        r.setProperty("objects", String.valueOf(wb.model().objects().size()));
        wb.screenshot(out.resolve("01-cell.png"));

        // Jog by joints through the spinners, then in Cartesian through the jog buttons.
        r.setProperty("q0", fmt(wb.model().q()));
        Workbench.onEdt(() -> {
            frame.jogPanel().setJointDegrees(0, 10);
            frame.jogPanel().setJointDegrees(1, 30);
        });
        r.setProperty("qJointJog", fmt(wb.model().q()));
        Pose before = wb.model().worldTtcp();
        AtomicReference<Boolean> ok = new AtomicReference<>(true);
        Workbench.onEdt(() -> {
            frame.jogPanel().setJogFrame(Workbench.JogFrame.WORLD);
            for (int i = 0; i < 5; i++) ok.set(ok.get() & frame.jogPanel().stepCartesian(2, -1)); // 5 x 10 mm down
        });
        Pose after = wb.model().worldTtcp();
        r.setProperty("cartesianJogOk", ok.get().toString());
        r.setProperty("cartesianDz", String.valueOf(after.z() - before.z()));
        r.setProperty("cartesianDxy", String.valueOf(Math.hypot(after.x() - before.x(), after.y() - before.y())));
        r.setProperty("cartesianAngle", String.valueOf(before.angleTo(after)));

        // Teach three targets (Teach action), moving between them with Cartesian jogs.
        Workbench.onEdt(() -> frame.action("teach").actionPerformed(null));
        Workbench.onEdt(() -> {
            frame.jogPanel().setJogFrame(Workbench.JogFrame.WORLD);
            for (int i = 0; i < 15; i++) frame.jogPanel().stepCartesian(1, 1); // +150 mm in y
            frame.action("teach").actionPerformed(null);
            frame.jogPanel().setJogFrame(Workbench.JogFrame.TOOL);
            for (int i = 0; i < 10; i++) frame.jogPanel().stepCartesian(0, 1); // 100 mm along tool x
            frame.action("teach").actionPerformed(null);
        });
        r.setProperty("targets", String.join(",", wb.model().targets().stream().map(Target::name).toList()));

        // Build a path: MoveJ to the first, MoveL to the others and back.
        Workbench.onEdt(() -> {
            for (String t : new String[] {"p10", "p20", "p30", "p10"}) {
                wb.model().select("target:" + t);
                frame.action(t.equals("p10") && wb.model().program().isEmpty() ? "add-movej" : "add-movel").actionPerformed(null);
            }
        });
        r.setProperty("program", String.join(";", wb.model().program().stream().map(Instruction::toString).toList()));
        AtomicReference<ProgramPlan> plan = new AtomicReference<>();
        Workbench.onEdt(() -> plan.set(frame.programPanel().check()));
        r.setProperty("checkOk", String.valueOf(plan.get().ok()));
        r.setProperty("duration", String.valueOf(plan.get().duration()));

        // An unreachable target is marked red and fails the check.
        Pose cur = wb.model().worldTtcp();
        Pose orientation = Pose.translation(cur.position().times(-1)).times(cur);
        Target far = new Target("p99", Pose.translation(3.2, 0, 1.0).times(orientation), wb.model().q(),
                wb.model().kinematics().confOf(wb.model().q()));
        Workbench.onEdt(() -> {
            wb.model().putTarget(far);
            wb.model().select("target:p99");
            frame.action("add-movel").actionPerformed(null);
            plan.set(frame.programPanel().check());
        });
        r.setProperty("checkWithFarOk", String.valueOf(plan.get().ok()));
        r.setProperty("farStatus", wb.model().status(far).name());
        Workbench.onEdt(() -> {
            frame.programPanel().showTime(plan.get().duration() * 0.4);
            wb.model().setShowFrames(true);
        });
        wb.screenshot(out.resolve("02-path.png"));
        Workbench.onEdt(() -> {
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

        // Cell layout: add and move a table, then save, reopen, and try a damaged copy.
        Workbench.onEdt(() -> {
            frame.action("add-table").actionPerformed(null);
            String id = wb.model().selection().substring(7);
            wb.placeObject(id, -0.2, -1.3, 0, Math.toRadians(30));
        });
        r.setProperty("objectsAfterAdd", String.valueOf(wb.model().objects().size()));
        wb.screenshot(out.resolve("03-layout.png"));
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
        r.setProperty("fps", String.valueOf(wb.app().fps()));
    }
}
