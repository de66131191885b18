package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.demo.DemoPrograms;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.Target;
import org.robopro.kinematics.Pose;
import org.robopro.programs.RapidParser;
import org.robopro.programs.rapid.RapidAstWriter;

/**
 * RAPID import, edit one move, export: every statement and item not edited comes out byte for
 * byte as it was read (the workbench's program is a view of the module's syntax tree).
 */
class RapidRoundTripWorkbenchTest {
    @TempDir Path dir;

    /** DemoWeld.mod with waits, I/O, comments, a procedure call, a loop and a second routine added to main. */
    static String withOtherStatements(String demoWeld) {
        String text = demoWeld.replaceFirst("(  PROC main\\(\\)\n    MoveAbsJ [^\n]*\n)", "$1"
                + "    ! clamp the plates, then weld\n"
                + "    SetDO doClamp, 1;\n"
                + "    WaitDI diClamped, 1\\\\MaxTime:=2;\n"
                + "    WaitTime 0.5;\n"
                + "    approach;\n"
                + "    FOR i FROM 1 TO 2 DO\n"
                + "      TPWrite \"pass\"\\\\Num:=i;\n"
                + "    ENDFOR\n");
        text = text.replace("ENDMODULE\n", "\n  PROC approach()\n    ! gas on before the arc\n    SetDO doGas, 1;\n  ENDPROC\nENDMODULE\n");
        return text;
    }

    /** The lines of {@code after} that differ from {@code before} (same line count asserted). */
    static List<String> changedLines(String before, String after) {
        String[] a = before.split("\n", -1), b = after.split("\n", -1);
        assertEquals(a.length, b.length, "line count\n" + after);
        List<String> out = new ArrayList<>();
        for (int k = 0; k < a.length; k++) if (!a[k].equals(b[k])) out.add(a[k] + "  ->  " + b[k]);
        return out;
    }

    private String roundTrip(String source, boolean withOthers) throws Exception {
        Path in = dir.resolve("DemoWeld.mod");
        Files.writeString(in, source);
        assertEquals(source, RapidAstWriter.write(RapidParser.parse(source, "DemoWeld.mod").tree()), "fixture in the writer's layout");
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            s.importRapid(in);
            List<Instruction> p = new ArrayList<>(s.model().program());
            if (withOthers) {
                assertTrue(p.stream().anyMatch(i -> i.toString().equals("SetDO doClamp, 1;")), p.toString());
                assertTrue(p.stream().anyMatch(i -> i.toString().equals("FOR i FROM 1 TO 2 DO ...")), p.toString());
            }
            // Unedited: the export is the file as read.
            Path out = Files.createDirectories(dir.resolve("out")).resolve("DemoWeld.mod");
            assertEquals(source, s.exportRapid(out, true), "import then export without an edit");
            // Edit one move's speed.
            int k = 0;
            while (p.get(k).type() != Instruction.Type.MOVEL) k++;
            Instruction i = p.get(k);
            p.set(k, new Instruction(i.type(), i.target(), 55, i.zoneMm(), i.via()));
            s.model().setProgram(p);
            String edited = s.exportRapid(out, true);
            List<String> changed = changedLines(source, edited);
            assertEquals(1, changed.size(), changed.toString());
            assertTrue(changed.get(0).matches(".*MoveL " + i.target() + ", v\\d+, fine, tTorch\\\\WObj:=wTable;  ->  .*MoveL "
                    + i.target() + ", \\[55,500,5000,1000\\], fine, tTorch\\\\WObj:=wTable;"), changed.toString());
            // Move that target 5 mm up: its declaration changes, nothing else.
            Target t = s.model().target(i.target()).orElseThrow();
            s.model().putTarget(t.withPose(Pose.translation(0, 0, 0.005).times(t.worldTtcp())));
            List<String> moved = changedLines(edited, s.exportRapid(out, true));
            assertEquals(1, moved.size(), moved.toString());
            assertTrue(moved.get(0).startsWith("  CONST robtarget " + i.target() + ":="), moved.toString());
            // Saved and reopened, the project keeps the module: the same export.
            String before = s.exportRapid(out, true);
            Path project = dir.resolve("cell.robopro.json");
            s.save(project);
            try (WorkbenchSession r = WorkbenchSession.open(project)) {
                assertEquals(s.model().program().size(), r.model().program().size());
                assertEquals(before, r.exportRapid(out, true), "after save and reopen");
            }
            return edited;
        }
    }

    @Test
    void demoWeld_importEditOneMoveExport_everyOtherLineAsRead() throws Exception {
        roundTrip(DemoPrograms.demoWeldText(), false);
    }

    @Test
    void moduleWithWaitsIoCallsComments_importEditOneMoveExport_everyOtherStatementAsRead() throws Exception {
        String edited = roundTrip(withOtherStatements(DemoPrograms.demoWeldText()), true);
        assertTrue(edited.contains("    WaitDI diClamped, 1\\MaxTime:=2;\n    WaitTime 0.5;\n    approach;\n"), edited);
        assertTrue(edited.contains("  PROC approach()\n    ! gas on before the arc\n    SetDO doGas, 1;\n  ENDPROC\n"), edited);
    }
}
