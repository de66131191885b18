package org.robopro.programs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.programs.rapid.RapidAstWriter;

/** The module is its syntax tree; the typed items are a view of it. */
class RapidModuleTest {
    static final String TEXT = """
            MODULE Cell
              ! cell program
              PERS tooldata tGun:=[TRUE,[[0,0,200],[1,0,0,0]],[2,[0,0,100],[1,0,0,0],0,0,0]];
              CONST robtarget p10:=[[600,0,500],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
              VAR num count:=0;

              PROC main()
                ! clamp, then weld
                SetDO doClamp, 1;
                WaitDI diClamped, 1\\MaxTime:=2;
                MoveJ p10, v500, z10, tGun;
                MoveL [[600,100,500],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]], v100, fine, tGun;
                WaitTime 0.5;
                count:=count+1;
                approach;
              ENDPROC

              PROC approach()
                MoveJ p10, v1000, z50, tGun;
              ENDPROC
            ENDMODULE
            """;

    @Test
    void parse_viewNodesAreTheTreesStatements() {
        RapidModule m = RapidParser.parse(TEXT, "Cell.mod");
        Procedure main = m.procedure("main").orElseThrow();
        RapidAst.Routine r = (RapidAst.Routine) m.tree().items().get(4);
        for (int k = 0; k < main.body().size(); k++) assertSame(r.body().get(k), m.node(main.body().get(k)).orElseThrow(), "statement " + k);
        assertTrue(main.body().get(2) instanceof AstStatement, "WaitDI with \\MaxTime stays tree");
        assertTrue(main.body().get(3) instanceof Move);
        assertEquals(TEXT, RapidAstWriter.write(m.tree()), "the tree writes back as read");
    }

    @Test
    void withItems_oneMoveEdited_everyOtherNodeKeptAndTextUnchangedElsewhere() {
        RapidModule m = RapidParser.parse(TEXT, "Cell.mod");
        Procedure main = m.procedure("main").orElseThrow();
        Move mv = (Move) main.body().get(3);
        List<Statement> body = new ArrayList<>(main.body());
        body.set(3, mv.withSpeedOverride(java.util.OptionalDouble.of(0.25), java.util.OptionalDouble.empty()));
        List<ModuleItem> items = new ArrayList<>(m.items());
        items.set(items.indexOf(main), main.withBody(body));
        RapidModule edited = m.withItems(items);
        RapidAst.Routine before = (RapidAst.Routine) m.tree().items().get(4), after = (RapidAst.Routine) edited.tree().items().get(4);
        for (int k = 0; k < before.body().size(); k++)
            if (k == 3) assertNotSame(before.body().get(k), after.body().get(k));
            else assertSame(before.body().get(k), after.body().get(k), "statement " + k + " kept");
        for (int k : new int[] {0, 1, 2, 3, 5}) assertSame(m.tree().items().get(k), edited.tree().items().get(k), "item " + k + " kept");
        String[] a = TEXT.split("\n"), b = RapidAstWriter.write(edited.tree()).split("\n");
        assertEquals(a.length, b.length);
        int changed = 0;
        for (int k = 0; k < a.length; k++) if (!a[k].equals(b[k])) { changed++; assertEquals("    MoveJ p10, v500\\V:=250, z10, tGun;", b[k]); }
        assertEquals(1, changed);
        // The view of the edited tree reads the edit back.
        Move read = (Move) edited.procedure("main").orElseThrow().body().get(3);
        assertEquals(0.25, read.v().getAsDouble(), 1e-15);
    }

    @Test
    void builtInCode_viewReadFromTheTreeItProduces() {
        RobTarget t = new RobTarget(new org.robopro.models.Vec3(0.6, 0.1, 0.5), new Quaternion(0, 0, 1, 0),
                new org.robopro.kinematics.ConfData(0, 0, 0, 0), ExtJoints.NONE);
        RapidModule m = RapidModule.builder("M").constant("p1", t).constant("p1", t)
                .procedure("main", List.of(Move.moveL(Ref.to("p1"), Ref.to("v100"), Ref.to("fine"), "tool0", null), new WaitTime(1)))
                .build();
        assertEquals(2, m.declarations().size(), "a name used twice is kept in the view (the export renames it)");
        RapidAst.Routine r = (RapidAst.Routine) m.tree().items().get(2);
        assertEquals("MoveL", ((RapidAst.Call) r.body().get(0)).name());
        SameMeaning.assertSame(t, m.declaration("p1").orElseThrow().value());
        assertTrue(RapidWriter.export(m).text().contains("p1_2"), "export renames the second p1");
    }
}
