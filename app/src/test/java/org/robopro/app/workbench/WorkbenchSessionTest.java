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
}
