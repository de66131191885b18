package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;
import org.robopro.programs.Declaration;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RobTarget;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;

class ProgramModuleTest {
    static WorkbenchModel model() {
        WorkbenchModel m = ProgramRunTest.modelWithTargets();
        Pose worldTuser = Pose.translation(0.8, -0.3, 0.7).times(Pose.rotZ(0.3));
        m.setWorkObjects(List.of(new WorkObject("wTable", worldTuser)));
        m.putTarget(m.target("p20").orElseThrow().withWobj("wTable"));
        m.putTarget(m.target("p15").orElseThrow().withWobj("wTable"));
        m.setProgram(List.of(new Instruction(Instruction.Type.MOVEJ, "p10", 500, 10),
                new Instruction(Instruction.Type.MOVEC, "p20", 100, 0, "p15"),
                new Instruction(Instruction.Type.MOVEL, "p10", 123, 7)));
        return m;
    }

    @Test
    void toRapid_targetInWorkObject_writtenInItsFrameWithConfOfTheSolutionUsed() {
        WorkbenchModel m = model();
        RapidModule mod = ProgramModule.toRapid(m, "Weld");
        RobTarget p20 = (RobTarget) mod.declaration("p20").map(Declaration::value).orElseThrow();
        Pose worldTuser = m.workObjects().get(0).worldTuser();
        Pose expected = worldTuser.inverse().times(m.target("p20").orElseThrow().worldTtcp());
        assertEquals(0, p20.pose().distanceTo(expected), 1e-12);
        assertEquals(0, p20.pose().angleTo(expected), 1e-9);
        Target t = m.target("p20").orElseThrow();
        double[] q = m.solveTcp(t.worldTtcp(), t.qTaught()).orElseThrow();
        assertEquals(m.kinematics().confOf(q), p20.robconf());
        String text = RapidWriter.export(mod).text();
        assertTrue(text.contains("MoveC p15, p20, v100, fine, torch\\WObj:=wTable;"), text);
        assertTrue(text.contains("MoveJ p10, v500, z10, torch;"), text);
        assertTrue(text.contains("PERS wobjdata wTable"), text);
    }

    @Test
    void toRapid_circlePointInAnotherWorkObject_writtenInlineInTheMovesWorkObject() {
        WorkbenchModel m = model();
        m.putTarget(m.target("p15").orElseThrow().withWobj(Target.WOBJ0));
        String text = RapidWriter.export(ProgramModule.toRapid(m, "Weld")).text();
        assertTrue(text.contains("MoveC [["), text);
        ProgramModule.Imported imp = ProgramModule.fromRapid(RapidParser.parseDetailed(text, "Weld.mod"), m, "main");
        Target via = imp.targets().stream().filter(t -> t.name().equals(imp.program().get(1).via())).findFirst().orElseThrow();
        assertEquals(0, via.worldTtcp().distanceTo(m.target("p15").orElseThrow().worldTtcp()), 1e-6);
    }

    @Test
    void fromRapid_exportedProgram_roundTripsTargetsAndInstructions() {
        WorkbenchModel m = model();
        String text = RapidWriter.export(ProgramModule.toRapid(m, "Weld")).text();
        // Into a cell without targets, so every target is read from the module (not found among the cell's).
        WorkbenchModel empty = model();
        for (Target t : empty.targets()) empty.removeTarget(t.name());
        ProgramModule.Imported imp = ProgramModule.fromRapid(RapidParser.parseDetailed(text, "Weld.mod"), empty, "main");
        assertEquals(m.program().size(), imp.program().size());
        for (int i = 0; i < m.program().size(); i++) {
            Instruction a = m.program().get(i), b = imp.program().get(i);
            assertEquals(a.type(), b.type());
            assertEquals(a.target(), b.target());
            assertEquals(a.via(), b.via());
            assertEquals(a.speedMmPerS(), b.speedMmPerS(), 1e-6);
            assertEquals(a.zoneMm(), b.zoneMm(), 1e-9);
        }
        for (Target b : imp.targets()) {
            Target a = m.target(b.name()).orElseThrow();
            assertEquals(0, a.worldTtcp().distanceTo(b.worldTtcp()), 1e-6, b.name());
            assertEquals(a.wobj(), b.wobj());
            assertEquals(ProgramModule.confUsed(m, m.kinematics(), a), b.conf(), "confdata of the IK solution the export used");
            // The joints found for the imported target reach it.
            assertEquals(0, m.worldTtcp(b.qTaught()).distanceTo(b.worldTtcp()), 1e-6, b.name());
        }
        assertEquals("torch", imp.tool().name());
        assertEquals(0, imp.tool().flangeTtcp().distanceTo(m.tool().flangeTtcp()), 1e-9);
        assertTrue(imp.notes().isEmpty(), imp.notes().toString());
    }

    @Test
    void fromRapid_inlineTargetsAbsJAndWaits_namedConvertedAndNoted() {
        WorkbenchModel m = model();
        String text = String.join("\n", "MODULE Other",
                "  PROC main()",
                "    MoveAbsJ [[0,20,10,0,50,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, z50, tool0;",
                "    MoveL [[1100,0,900],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v200, fine, tool0;",
                "    WaitTime 0.5;",
                "  ENDPROC",
                "ENDMODULE", "");
        ProgramModule.Imported imp = ProgramModule.fromRapid(RapidParser.parseDetailed(text, "Other.mod"), m, "main");
        assertEquals(3, imp.program().size());
        assertEquals(Instruction.Type.MOVEABSJ, imp.program().get(0).type(), "MoveAbsJ stays MoveAbsJ");
        assertEquals(Instruction.Type.MOVEL, imp.program().get(1).type());
        assertEquals(Instruction.Type.RAPID, imp.program().get(2).type(), "WaitTime kept as written");
        assertEquals("WaitTime 0.5;", imp.program().get(2).statementText());
        assertEquals("tool0", imp.tool().name());
        Target t = imp.targets().stream().filter(x -> x.name().equals(imp.program().get(1).target())).findFirst().orElseThrow();
        assertEquals(1.1, t.worldTtcp().x(), 1e-9);
        assertEquals(0.9, t.worldTtcp().z(), 1e-9);
        assertTrue(imp.notes().stream().anyMatch(n -> n.contains("kept as written")), imp.notes().toString());
        // MoveAbsJ's target holds its joints and is where they put the TCP.
        Target abs = imp.targets().stream().filter(x -> x.name().equals(imp.program().get(0).target())).findFirst().orElseThrow();
        assertEquals(Math.toRadians(20), abs.qTaught()[1], 1e-12);
        assertEquals(0, m.kinematics().flange(abs.qTaught()).distanceTo(abs.worldTtcp()), 1e-9);
    }

    @Test
    void fromRapid_unknownTarget_inputExceptionWithLineAndColumn() {
        WorkbenchModel m = model();
        String text = "MODULE Bad\n  PROC main()\n    MoveL nowhere, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
        InputException e = assertThrows(InputException.class,
                () -> ProgramModule.fromRapid(RapidParser.parseDetailed(text, "Bad.mod"), m, "main"));
        assertEquals(3, e.line());
        assertTrue(e.getMessage().contains("nowhere"), e.getMessage());
    }
}
