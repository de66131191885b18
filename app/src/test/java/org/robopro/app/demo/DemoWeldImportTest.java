package org.robopro.app.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.Instruction;
import org.robopro.app.workbench.model.Target;
import org.robopro.app.workbench.model.WorkObject;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.CellFile;
import org.robopro.programs.RapidWriter;

/** The demo's weld program (DemoWeld.mod) imported into the workbench's welding cell. */
class DemoWeldImportTest {
    @TempDir Path dir;

    @Test
    void importDemoWeld_reusesTheCellsWorkObjectKeepsMoveAbsJAndAddsNoDuplicates() throws Exception {
        var cell = CellFile.shipped("irb2000-welding");
        WeldProgram weld = WeldProgram.teach(cell, KinematicModel.build(CellFile.loadRobot(cell, null)), 2);
        Path mod = dir.resolve("DemoWeld.mod");
        Files.writeString(mod, RapidWriter.export(weld.module).text());
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            List<WorkObject> before = s.model().workObjects();
            s.importRapid(mod);
            // wTable has wobj_table's frame: the cell's work object is used, none added.
            assertEquals(before, s.model().workObjects(), "no duplicate work object beside wobj_table");
            List<Instruction> p = s.model().program();
            assertEquals(Instruction.Type.MOVEABSJ, p.get(0).type(), "MoveAbsJ stays MoveAbsJ");
            assertEquals(Instruction.Type.MOVEABSJ, p.get(p.size() - 1).type());
            assertEquals("jHome", p.get(0).target());
            assertEquals("jHome", p.get(p.size() - 1).target(), "the second MoveAbsJ jHome is the same target, no jHome_N");
            assertTrue(s.model().targets().stream().noneMatch(t -> t.name().startsWith("jHome_")), s.model().targets().toString());
            for (Target t : s.model().targets())
                if (t.name().startsWith("pW")) assertEquals("wobj_table", t.wobj(), t.name());
            int targets = s.model().targets().size();
            // Importing again adds nothing: every target and work object is found by value.
            s.importRapid(mod);
            assertEquals(targets, s.model().targets().size());
            assertEquals(before, s.model().workObjects());
            // Exported again, MoveAbsJ goes to the jointtarget jHome.
            String text = s.exportRapid(dir.resolve("Again.mod"), false);
            assertTrue(text.contains("CONST jointtarget jHome"), text);
            assertTrue(text.contains("MoveAbsJ jHome"), text);
        }
    }
}
