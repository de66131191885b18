package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.Target;
import org.robopro.kinematics.Pose;

/** The workbench's operations on the headless session: no display, no Swing, no 3D view. */
class WorkbenchSessionTest {
    @TempDir Path dir;
    private WorkbenchSession s;

    @BeforeEach
    void open() throws Exception {
        System.setProperty("robopro.autosaveDir", dir.resolve("autosave").toString());
        s = WorkbenchSession.open(null);
    }

    @AfterEach
    void close() { s.close(); }

    @Test
    void sessionPackage_importsNeitherTheWindowNorTheSceneNorAwt() throws Exception {
        // The headless side must load and run without a display: nothing in its package may
        // reach for the Swing window, the jME scene or AWT.
        Path pkg = Path.of("src/main/java/org/robopro/app/workbench");
        int files = 0;
        try (var list = Files.list(pkg)) {
            for (Path f : list.filter(x -> x.toString().endsWith(".java")).toList()) {
                files++;
                for (String line : Files.readAllLines(f)) {
                    if (!line.startsWith("import ")) continue;
                    for (String bad : new String[] {"org.robopro.app.workbench.ui", "org.robopro.app.workbench.scene", "com.jme3", "java.awt"})
                        assertFalse(line.contains(bad), f.getFileName() + ": " + line);
                }
            }
        }
        assertTrue(files >= 3, "session, project store and controller session found in " + pkg.toAbsolutePath());
        assertFalse(s.model().objects().isEmpty(), "the welding cell has objects");
    }

    @Test
    void jogCartesian_worldDown_movesTcpTenMillimetresKeepingOrientation() {
        Pose before = s.model().worldTtcp();
        assertTrue(s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0, -0.01, 0, 0, 0));
        Pose after = s.model().worldTtcp();
        assertEquals(-0.01, after.z() - before.z(), 1e-7);
        assertEquals(0, Math.hypot(after.x() - before.x(), after.y() - before.y()), 1e-7);
        assertEquals(0, before.angleTo(after), 1e-7);
    }

    @Test
    void jogCartesian_farOutOfReach_refusedAndRobotStays() {
        double[] q = s.model().q();
        assertFalse(s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 10, 0, 0, 0, 0, 0));
        assertArrayEquals(q, s.model().q(), 0);
        assertTrue(s.log().get(s.log().size() - 1).startsWith("Jog refused"), s.log().toString());
    }

    @Test
    void teachMoveCheckExportImport_roundTripsTheProgram() throws Exception {
        Target a = s.teach();
        s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0.1, 0, 0, 0, 0);
        Target b = s.teach();
        s.addMove(Instruction.Type.MOVEJ, a.name(), 200, 10);
        s.addMove(Instruction.Type.MOVEL, b.name(), 100, 0);
        var run = s.checkProgram();
        assertTrue(run.ok(), run.problemLines().toString());
        Path mod = dir.resolve("p.mod");
        String text = s.exportRapid(mod, false);
        assertTrue(text.contains("MoveL " + b.name()), text);
        assertThrows(java.io.IOException.class, () -> s.exportRapid(mod, false), "no silent overwrite");
        s.model().setProgram(java.util.List.of());
        s.importRapid(mod);
        assertEquals(2, s.model().program().size());
        assertEquals(Instruction.Type.MOVEL, s.model().program().get(1).type());
        assertEquals(b.name(), s.model().program().get(1).target());
    }

    /**
     * The user's steps of the workbench scenario without a window: from the ready pose (axes 4
     * and 6 at 0) jog the joints and down in Cartesian, teach three targets, program them, export
     * RAPID and import it back. Every move of the imported program is reachable in its target's
     * configuration, the same answer as before the export, and the same on every run.
     */
    @Test
    void teachAtReadyPoseExportImport_importedProgramReachableInEachTargetsOwnConfiguration() throws Exception {
        s.jogJointDeg(0, 10);
        s.jogJointDeg(1, 30);
        for (int i = 0; i < 5; i++) assertTrue(s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0, -0.01, 0, 0, 0));
        assertEquals(0, Math.toDegrees(s.model().q()[3]), 1e-9, "axis 4 stays on its quadrant boundary");
        Target p10 = s.teach();
        for (int i = 0; i < 15; i++) s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0.01, 0, 0, 0, 0);
        s.teach();
        for (int i = 0; i < 10; i++) s.jogCartesian(WorkbenchSession.JogFrame.TOOL, 0.01, 0, 0, 0, 0, 0);
        s.teach();
        for (String t : new String[] {"p10", "p20", "p30", "p10"})
            s.addMove(t.equals("p10") && s.model().program().isEmpty() ? Instruction.Type.MOVEJ : Instruction.Type.MOVEL, t, 500, 10);
        var before = s.checkProgram();
        assertTrue(before.ok() && before.steps().stream().allMatch(x -> x.problems().isEmpty()), before.problemLines().toString());
        Path mod = dir.resolve("Weld.mod");
        String text = s.exportRapid(mod, false);
        assertTrue(text.contains("CONST robtarget p10:=") && text.contains(",[0,0,0,0],"), "p10 in its taught configuration:\n" + text);
        s.importRapid(mod);
        assertTrue(s.model().programSource().isPresent(), "the program is now a view of the imported module");
        var after = s.checkProgram();
        assertEquals(4, after.steps().size());
        for (var st : after.steps())
            assertTrue(st.ok() && st.problems().isEmpty(), "instruction " + (st.index() + 1) + ": " + st.message() + "\n" + text);
        for (int i = 0; i < 4; i++) assertEquals(before.steps().get(i).seconds(), after.steps().get(i).seconds(), 1e-3, "instruction " + (i + 1));
        assertEquals(p10.conf(), s.model().target("p10").orElseThrow().conf());
    }

    @Test
    void addPlaceDeleteObject_andSaveOpen() throws Exception {
        int n = s.model().objects().size();
        CellObject t = s.addObject(CellObject.Kind.TABLE);
        s.placeObject(t.id(), 1.5, -0.5, 0, Math.toRadians(30));
        assertEquals(n + 1, s.model().objects().size());
        assertEquals(1.5, s.model().object(t.id()).orElseThrow().worldTobject().x(), 1e-12);
        Path p = dir.resolve("cell.robopro.json");
        s.save(p);
        assertFalse(s.model().dirty());
        s.deleteSelection();
        assertEquals(n, s.model().objects().size());
        s.openProject(p);
        assertEquals(n + 1, s.model().objects().size());
        assertEquals(-0.5, s.model().object(t.id()).orElseThrow().worldTobject().y(), 1e-9);
        assertTrue(Files.exists(p));
    }

    @Test
    void openProject_damagedFile_throwsAndKeepsTheCell() throws Exception {
        Path bad = dir.resolve("bad.robopro.json");
        Files.writeString(bad, "{ \"format\": \"robopro-project\", ");
        int n = s.model().objects().size();
        assertThrows(Exception.class, () -> s.openProject(bad));
        assertEquals(n, s.model().objects().size());
    }

    @Test
    void logListener_seesEveryLine() {
        var seen = new java.util.ArrayList<String>();
        s.addLogListener(seen::add);
        s.addObject(CellObject.Kind.PART);
        assertEquals(1, seen.size());
        assertTrue(seen.get(0).startsWith("Added Part"), seen.toString());
    }

    // ---- undo and redo -------------------------------------------------------------------

    @Test
    void undoRedo_addTable_removesAndRestoresIt() {
        int n = s.model().objects().size();
        CellObject t = s.addObject(CellObject.Kind.TABLE);
        assertEquals("Add " + t.name(), s.model().history().undoLabel().orElseThrow());
        assertTrue(s.undo());
        assertEquals(n, s.model().objects().size());
        assertTrue(s.model().object(t.id()).isEmpty());
        assertEquals("Add " + t.name(), s.model().history().redoLabel().orElseThrow());
        assertTrue(s.redo());
        assertEquals(t, s.model().object(t.id()).orElseThrow());
        assertFalse(s.redo(), "nothing more to redo");
    }

    @Test
    void undo_teachAndMoves_stepByStepInReverseOrder() {
        Target a = s.teach();
        s.addMove(Instruction.Type.MOVEJ, a.name(), 200, 10);
        s.addMove(Instruction.Type.MOVEL, a.name(), 100, 0);
        assertEquals(2, s.model().program().size());
        s.undo();
        assertEquals(1, s.model().program().size());
        assertEquals(Instruction.Type.MOVEJ, s.model().program().get(0).type());
        s.undo();
        assertTrue(s.model().program().isEmpty());
        assertTrue(s.model().target(a.name()).isPresent());
        s.undo();
        assertTrue(s.model().target(a.name()).isEmpty(), "the taught target is taken back too");
        // A new edit after undo drops the redo branch.
        s.addObject(CellObject.Kind.PART);
        assertFalse(s.redo());
    }

    @Test
    void undo_deletedTargetWithItsMoves_bringsBothBack() {
        Target a = s.teach();
        s.addMove(Instruction.Type.MOVEJ, a.name(), 200, 10);
        s.model().select("target:" + a.name());
        s.deleteSelection();
        assertTrue(s.model().program().isEmpty());
        s.undo();
        assertTrue(s.model().target(a.name()).isPresent());
        assertEquals(1, s.model().program().size(), "one undo restores the target and the move that used it");
    }

    @Test
    void placeObject_repeatedQuickly_isOneUndoStep() {
        CellObject t = s.addObject(CellObject.Kind.TABLE);
        Pose start = s.model().object(t.id()).orElseThrow().worldTobject();
        for (int i = 1; i <= 10; i++) s.placeObject(t.id(), 1 + 0.01 * i, -1, 0, 0); // a spinner held down
        s.undo();
        assertEquals(0, start.distanceTo(s.model().object(t.id()).orElseThrow().worldTobject()), 1e-12);
        s.undo();
        assertTrue(s.model().object(t.id()).isEmpty());
    }

    @Test
    void undo_editsOutsideTheSession_toolRobotProgram_areUndoableToo() {
        var tool = s.model().tool();
        s.model().setTool(new org.robopro.app.workbench.model.Tool("t2", Pose.translation(0, 0, 0.3), 0.02, 0.2, 1.5));
        assertEquals("Edit tool", s.model().history().undoLabel().orElseThrow());
        s.undo();
        assertEquals(tool, s.model().tool());
        var robot = s.model().robot();
        s.model().setRobot("puma560", org.robopro.models.RobotLibrary.shipped("puma560"));
        assertEquals("Change robot", s.model().history().undoLabel().orElseThrow());
        s.undo();
        assertEquals(robot, s.model().robot());
        assertEquals(robot.dof(), s.model().q().length);
    }

    /**
     * Applying a calibration is an edit like any other: Undo takes the calibrated model out of use
     * (RAPID exports nominal again, the project's calibration reference back), Redo puts it back,
     * and stopping compensation is undone the same way. The robot file written stays on disk.
     */
    @Test
    void undo_applyCalibration_exportsNominalAgain_redoCompensatesAgain() throws Exception {
        var trial = org.robopro.world.Scenario.named("null irb2000, 50 poses").trial(3);
        Path file = dir.resolve("campaign.csv");
        Files.writeString(file, trial.campaign().text());
        var r = s.calibrate(s.loadMeasurements(file), org.robopro.calibration.Cancellation.NONE, org.robopro.calibration.Progress.NONE);
        Target a = s.teach();
        s.addMove(Instruction.Type.MOVEJ, a.name(), 200, 10);
        Path nominal = dir.resolve("Nominal.mod"), before = dir.resolve("Before.mod");
        s.exportRapid(nominal, false);
        String referenceBefore = s.model().calibrationReference();

        Path robotFile = dir.resolve("irb2000-calibrated.robot.json");
        s.applyCalibration(r, robotFile, file.toString(), false);
        assertTrue(s.calibratedModel().isPresent());
        assertEquals(robotFile.toString(), s.model().calibrationReference());
        assertEquals("Apply calibration irb2000-calibrated.robot.json", s.model().history().undoLabel().orElseThrow());
        Path compensated = dir.resolve("Compensated.mod");
        s.exportRapid(compensated, false);
        assertFalse(sameProgram(nominal, compensated), "the applied calibration compensates the export");

        s.undo();
        assertTrue(s.calibratedModel().isEmpty(), "undo takes the calibration out of use");
        assertEquals(referenceBefore, s.model().calibrationReference());
        s.exportRapid(before, false);
        assertTrue(sameProgram(nominal, before), "after undo the export is nominal again");
        assertTrue(Files.exists(robotFile), "the written robot file stays");

        s.redo();
        assertEquals(r.calibrated(), s.calibratedModel().orElseThrow());
        assertEquals(robotFile.toString(), s.model().calibrationReference());

        s.clearCalibration();
        assertTrue(s.calibratedModel().isEmpty());
        s.clearCalibration(); // stopping again changes nothing and is no edit: one undo still brings the calibration back
        s.undo();
        assertEquals(r.calibrated(), s.calibratedModel().orElseThrow(), "stopping compensation is undone too");
    }

    private static boolean sameProgram(Path a, Path b) throws java.io.IOException {
        String na = a.getFileName().toString().replace(".mod", ""), nb = b.getFileName().toString().replace(".mod", "");
        return Files.readString(a).replace(na, "X").equals(Files.readString(b).replace(nb, "X"));
    }

    @Test
    void undo_backToTheSavedState_isNotDirty() throws Exception {
        s.save(dir.resolve("u.robopro.json"));
        s.addObject(CellObject.Kind.TABLE);
        assertTrue(s.model().dirty());
        s.undo();
        assertFalse(s.model().dirty(), "the cell is as saved again");
        s.redo();
        assertTrue(s.model().dirty());
    }

    @Test
    void jogging_isNotAnEdit() {
        s.jogJointDeg(0, 20);
        assertFalse(s.undo(), "nothing to undo after jogging");
    }

    @Test
    void openProject_forgetsTheHistory() throws Exception {
        s.addObject(CellObject.Kind.TABLE);
        Path p = dir.resolve("h.robopro.json");
        s.save(p);
        s.openProject(p);
        assertFalse(s.undo());
    }

    // ---- autosave ------------------------------------------------------------------------

    @Test
    void save_underAName_removesTheUntitledAutosave() throws Exception {
        Path untitled = ProjectStore.autosavePath(null);
        Files.createDirectories(untitled.getParent());
        s.addObject(CellObject.Kind.TABLE);
        ProjectStore.write(s.model().snapshot(), untitled, true); // as the autosave timer would
        assertTrue(ProjectStore.recoverable(null).isPresent());
        s.save(dir.resolve("named.robopro.json"));
        assertFalse(Files.exists(untitled), "no false recovery offer at the next start");
        assertTrue(ProjectStore.recoverable(dir.resolve("named.robopro.json")).isEmpty());
    }

    // ---- project round trip ----------------------------------------------------------------

    @Test
    void saveOpen_teachInWobjAndRobotPose_reopenAsSaved() throws Exception {
        String wobj = s.model().workObjects().get(0).name();
        s.model().setActiveWorkObject(wobj);
        s.jogJointDeg(0, 12.5);
        s.jogJointDeg(4, 70);
        double[] q = s.model().q();
        Path p = dir.resolve("rt.robopro.json");
        s.save(p);
        try (WorkbenchSession other = WorkbenchSession.open(p)) {
            assertEquals(wobj, other.model().activeWorkObject());
            assertArrayEquals(q, other.model().q(), 1e-12);
            ProjectRoundTrip.assertSame(s.model().snapshot(), other.model().snapshot());
        }
    }

    @Test
    void describe_controllerStatus_inWordsNotARecordDump() {
        String idle = WorkbenchSession.describe(new org.robopro.comms.ControllerStatus(
                org.robopro.comms.ControllerStatus.State.IDLE, "Weld", 0, null, "", 12.4));
        assertEquals("idle, program Weld, no errors, clock 12.40 s", idle);
        assertFalse(idle.contains("ControllerStatus["), idle);
    }
}
