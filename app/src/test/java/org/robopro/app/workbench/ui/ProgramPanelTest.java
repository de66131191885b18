package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JSlider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.Target;

/** The program panel: as it first opens, and what its Check column and timeline show. */
class ProgramPanelTest {
    @TempDir Path dir;

    @Test
    void opened_teachInShowsTheActiveWorkObjectAndListsEveryWorkObject() throws Exception {
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            ProgramPanel p = new ProgramPanel(s);
            JComboBox<?> wobj = (JComboBox<?>) find(p, "teach-wobj");
            assertEquals(s.model().activeWorkObject(), wobj.getSelectedItem(), "the work object new targets are taught in");
            assertEquals(1 + s.model().workObjects().size(), wobj.getItemCount());
            assertEquals(Target.WOBJ0, wobj.getItemAt(0));
        }
    }

    /**
     * An imported module whose main calls routines: the call's row shows the outcome of the
     * motions it ran (a FAIL for the unreachable one, not a blank), a wait's row shows nothing.
     */
    @Test
    void importedCalls_callRowShowsTheOutcomeOfTheMotionsItRan() throws Exception {
        System.setProperty("robopro.autosaveDir", dir.resolve("autosave").toString());
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            Target p10 = s.teach();
            s.addMove(Instruction.Type.MOVEJ, p10.name(), 500, 10);
            String text = s.exportRapid(dir.resolve("Calls.mod"), false);
            String moveJ = text.lines().filter(l -> l.trim().startsWith("MoveJ p10")).findFirst().orElseThrow().trim();
            String decl = text.lines().filter(l -> l.trim().startsWith("CONST robtarget p10:=")).findFirst().orElseThrow();
            // pFar: p10 moved to x = 5 m, out of the IRB 2000's reach
            String far = decl.replace("p10:=[[", "pFar:=[[").replaceFirst("pFar:=\\[\\[[-0-9.E+]+,", "pFar:=[[5000,");
            String calls = text.replace(decl, decl + "\n" + far)
                    .replace("    " + moveJ + "\n  ENDPROC", "    near;\n    WaitTime 0.1;\n    far;\n  ENDPROC\n"
                            + "  PROC near()\n    " + moveJ + "\n  ENDPROC\n"
                            + "  PROC far()\n    " + moveJ.replace("MoveJ p10", "MoveL pFar") + "\n  ENDPROC");
            Path mod = dir.resolve("Calls2.mod");
            Files.writeString(mod, calls);
            s.importRapid(mod);
            assertEquals(3, s.model().program().size(), calls);
            ProgramPanel p = new ProgramPanel(s);
            p.check();
            List<String> col = p.checkColumn();
            assertTrue(col.get(0).startsWith("ok "), "near: " + col);
            assertEquals("", col.get(1), "a wait moves nothing: " + col);
            assertTrue(col.get(2).startsWith("FAIL unreachable"), "far: " + col + "\n" + calls);
        }
    }

    /** The timeline's label and slider follow the shown time and the current plan's duration. */
    @Test
    void timeline_followsTheShownTimeAndTheCheckedProgramsDuration() throws Exception {
        System.setProperty("robopro.autosaveDir", dir.resolve("autosave").toString());
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            Target a = s.teach();
            s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0.15, 0, 0, 0, 0);
            Target b = s.teach();
            s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0.1, 0, 0, 0, 0, 0);
            Target c = s.teach();
            for (Target t : new Target[] {a, b, c}) s.addMove(Instruction.Type.MOVEL, t.name(), 500, 10);
            ProgramPanel p = new ProgramPanel(s);
            JLabel time = (JLabel) find(p, "timeline-time");
            JSlider slider = (JSlider) find(p, "timeline");
            double d = p.check().duration();
            assertTrue(d > 0.2, "duration " + d);
            assertEquals(String.format(java.util.Locale.ROOT, "0.00 / %.2f s", d), time.getText());
            p.showTime(0.4 * d);
            assertEquals(String.format(java.util.Locale.ROOT, "%.2f / %.2f s", 0.4 * d, d), time.getText());
            assertEquals(400, slider.getValue(), "the slider stands where the label says");
            // The last move removed: the background check's plan has another duration, and the timeline says so.
            s.model().setProgram(s.model().program().subList(0, 2));
            s.awaitPathCheck();
            p.refresh();
            double d2 = s.pathChecker().latest().run().duration();
            assertTrue(d2 < d, d2 + " vs " + d);
            assertEquals(String.format(java.util.Locale.ROOT, "%.2f / %.2f s", Math.min(0.4 * d, d2), d2), time.getText());
        }
    }

    private static Component find(Container c, String name) {
        for (Component k : c.getComponents()) {
            if (name.equals(k.getName())) return k;
            if (k instanceof Container kc) {
                Component f = find(kc, name);
                if (f != null) return f;
            }
        }
        return null;
    }
}
