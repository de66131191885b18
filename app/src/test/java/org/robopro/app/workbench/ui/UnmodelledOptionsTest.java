package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.programs.RapidParser;
import org.robopro.programs.rapid.RapidAst;

/** The options of an imported move that an edit in the program panel does not write back are named to the user. */
class UnmodelledOptionsTest {

    private static List<RapidAst.Stmt> main(String body) {
        String text = "MODULE M\n"
                + "  CONST robtarget p10 := [[500,0,800],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n"
                + "  PERS wobjdata w1 := [FALSE,TRUE,\"\",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];\n"
                + "  PROC main()\n" + body + "  ENDPROC\nENDMODULE\n";
        for (RapidAst.Item it : RapidParser.parse(text, "M.mod").tree().items())
            if (it instanceof RapidAst.Routine r && r.name().equals("main")) return r.body();
        throw new AssertionError("no main");
    }

    @Test
    void namesEveryOptionButTheWorkObject() {
        List<RapidAst.Stmt> s = main("    MoveL p10, v100\\V:=500, z10\\Z:=5, tool0\\WObj:=w1;\n"
                + "    MoveJ \\Conc, p10, v100, z10, tool0;\n"
                + "    MoveL p10, v100, fine, tool0\\WObj:=w1;\n"
                + "    MoveL ToPoint:=p10, Speed:=v100, Zone:=z10, Tool:=tool0;\n");
        assertEquals("\\V, \\Z", ProgramPanel.unmodelledOptions(s.get(0)));
        assertEquals("\\Conc", ProgramPanel.unmodelledOptions(s.get(1)));
        assertEquals("", ProgramPanel.unmodelledOptions(s.get(2)));
        assertEquals("", ProgramPanel.unmodelledOptions(s.get(3)));
        assertEquals("", ProgramPanel.unmodelledOptions(null));
    }
}
