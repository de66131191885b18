package org.robopro.programs.rapid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.OptionalDouble;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.ConfData;
import org.robopro.models.InputException;
import org.robopro.programs.JointTarget;
import org.robopro.programs.Move;
import org.robopro.programs.ProcCall;
import org.robopro.programs.Procedure;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidValue;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SameMeaning;
import org.robopro.programs.ToolData;
import org.robopro.programs.WaitTime;
import org.robopro.programs.ZoneData;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;

class RapidParserTest {

    static String fixture(String name) {
        try (InputStream in = RapidParserTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void parse_handWrittenFixture_readsEveryDeclarationAndInstruction() {
        RapidModule m = RapidParser.parse(fixture("PickPlace.mod"), "PickPlace.mod");
        assertEquals("PickPlace", m.name());
        assertEquals(11, m.declarations().size());
        RobTarget pick = (RobTarget) m.declaration("ppick").orElseThrow().value();
        assertEquals(0.100, pick.trans().x(), 1e-15);
        assertEquals(0.020, pick.trans().z(), 1e-15);
        assertEquals(new ConfData(0, 0, 0, 0), pick.robconf());
        assertTrue(pick.extax().allUnused());
        JointTarget home = (JointTarget) m.declaration("jHome").orElseThrow().value();
        assertEquals(Math.toRadians(30), home.robax(4), 1e-15);
        ToolData g = (ToolData) m.declaration("tGripper").orElseThrow().value();
        assertEquals(0.150, g.tframe().trans().z(), 1e-15);
        assertEquals(2.5, g.tload().mass());
        assertEquals(RapidAst.Scope.LOCAL, m.declaration("zSoft").orElseThrow().scope());
        assertEquals("pick \"fast\"", ((RapidValue.Str) m.declaration("sMsg").orElseThrow().value()).value());
        Procedure main = m.procedure("main").orElseThrow();
        assertEquals(7, main.body().size());
        Move absJ = (Move) main.body().get(0);
        assertTrue(absJ.noEOffs());
        assertInstanceOf(ProcCall.class, main.body().get(1));
        Move circ = (Move) main.body().get(3);
        assertEquals(Move.Kind.MOVE_C, circ.kind());
        assertInstanceOf(Ref.Inline.class, circ.toPoint());
        assertEquals("wobjConveyor", circ.wobj().orElseThrow());
        Move slow = (Move) main.body().get(4);
        assertEquals(OptionalDouble.of(0.080), slow.v());
        assertEquals(new WaitTime(0.5), main.body().get(5));
        assertInstanceOf(Move.class, main.body().get(6));
        Procedure pick2 = m.procedure("PICK").orElseThrow();
        assertTrue(!pick2.local());
        assertEquals(5, pick2.body().size(), "trailing comment is a statement of its own");
        Move conc = (Move) pick2.body().get(4);
        assertTrue(conc.conc());
        assertEquals(OptionalDouble.of(0.8), conc.t());
        assertEquals(OptionalDouble.of(0.0), ((Move) pick2.body().get(2)).z());
    }

    @Test
    void exportParse_handWrittenFixture_sameMeaningAndValidForRapidchecker() {
        RapidModule m = RapidParser.parse(fixture("PickPlace.mod"), "PickPlace.mod");
        String out = RapidWriter.export(m).text();
        SameMeaning.assertSame(m, RapidParser.parse(out, "out.mod"));
        assertEquals(out, RapidWriter.export(RapidParser.parse(out, "out.mod")).text());
        RapidChecker.assertValid("PickPlace.mod", out);
    }

    @Test
    void parse_predefinedZone_keptAsName() {
        RapidModule m = RapidParser.parse("MODULE M\n PROC main()\n  MoveL [[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, z10, tool0;\n ENDPROC\nENDMODULE\n", "m");
        Move mv = (Move) m.procedure("main").orElseThrow().body().get(0);
        assertEquals(Ref.to("z10"), mv.zone());
        assertEquals(0.010, ZoneData.predefined("Z10").orElseThrow().pzoneTcp(), 1e-15);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', value = {
            "if without ENDIF    | MODULE M\\n  PROC main()\\n    IF x THEN\\n  ENDPROC\\nENDMODULE | 4 | 3 | ENDIF, found 'ENDPROC'",
            "call with brackets  | MODULE M\\n  PROC main()\\n    SetDO(do1, 1);\\n  ENDPROC\\nENDMODULE | 3 | 10 | without parentheses",
            "missing argument    | MODULE M\\n  PROC main()\\n    MoveL p1, v100, z10;\\n  ENDPROC\\nENDMODULE | 3 | 5 | MoveL needs 4 arguments",
            "missing comma       | MODULE M\\n  PROC main()\\n    MoveL p1 v100, z10, tool0;\\n  ENDPROC\\nENDMODULE | 3 | 14 | expected ',' or ';'",
            "bad module option   | MODULE M(SHARED)\\nENDMODULE | 1 | 10 | expected SYSMODULE",
            "option out of place | MODULE M\\n  PROC main()\\n    MoveL p1, v100\\WObj:=w, z10, tool0;\\n  ENDPROC\\nENDMODULE | 3 | 19 | not in its place",
            "bad quaternion      | MODULE M\\n  CONST robtarget p:=[[0,0,0],[0,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\\nENDMODULE | 2 | 31 | not unit",
            "short robtarget     | MODULE M\\n  CONST robtarget p:=[[0,0,0],[1,0,0,0],[0,0,0,0]];\\nENDMODULE | 2 | 22 | expected 4 components",
            "fractional conf     | MODULE M\\n  CONST robtarget p:=[[0,0,0],[1,0,0,0],[0,0.5,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\\nENDMODULE | 2 | 44 | expected an integer",
            "record without end  | MODULE M\\n  RECORD r\\n    num a;\\nENDMODULE | 4 | 1 | 'ENDMODULE' is a reserved word",
            "array of 4 dims     | MODULE M\\n  VAR num a{1,2,3,4};\\nENDMODULE | 2 | 11 | at most 3 dimensions",
            "wrong ref type      | MODULE M\\n  CONST jointtarget j:=[[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\\n  PROC main()\\n    MoveL j, v100, z10, tool0;\\n  ENDPROC\\nENDMODULE | 4 | 11 | a robtarget is needed",
            "duplicate name      | MODULE M\\n  VAR num a:=1;\\n  VAR num A:=2;\\nENDMODULE | 3 | 11 | name already used on line 2",
            "no ENDMODULE        | MODULE M\\n  VAR num a:=1;\\n | 3 | 1 | ENDMODULE missing",
            "no ENDPROC          | MODULE M\\n  PROC main()\\n    WaitTime 1;\\nENDMODULE | 4 | 1 | ENDPROC missing before ENDMODULE",
            "bad character       | MODULE M\\n  VAR num a:=1 # 2;\\nENDMODULE | 2 | 16 | unexpected character '#'",
            "chained comparison  | MODULE M\\n  VAR bool a:=1 < 2 < 3;\\nENDMODULE | 2 | 21 | do not chain",
            "text after module   | MODULE M\\nENDMODULE\\nMODULE N\\n | 3 | 1 | text after ENDMODULE",
            "long identifier     | MODULE M\\n  VAR num abcdefghijabcdefghijabcdefghijabc:=1;\\nENDMODULE | 2 | 11 | longer than 32",
            "func without end    | MODULE M\\n  FUNC num f()\\n    RETURN 1;\\n  PROC p()\\n  ENDPROC\\nENDMODULE | 4 | 3 | ENDFUNC missing before PROC",
            "local routine data  | MODULE M\\n  PROC main()\\n    LOCAL VAR num i;\\n  ENDPROC\\nENDMODULE | 3 | 5 | ENDPROC missing before LOCAL",
            "V and T             | MODULE M\\n  PROC main()\\n    MoveL p1, v100\\V:=5\\T:=2, z10, tool0;\\n  ENDPROC\\nENDMODULE | 3 | 5 | exclude each other",
    })
    void parse_unsupportedOrMalformed_inputExceptionWithLineAndColumn(String what, String text, int line, int col, String msg) {
        InputException e = assertThrows(InputException.class, () -> RapidParser.parse(text.replace("\\n", "\n"), "bad.mod"));
        assertEquals("bad.mod", e.file());
        assertTrue(e.getMessage().contains(msg), () -> what + ": " + e.getMessage());
        assertEquals(line, e.line(), () -> what + ": " + e.getMessage());
        assertEquals(col, e.column(), () -> what + ": " + e.getMessage());
    }

    @Test
    void parse_initialiserNamingPredefinedData_copiesItsValue() {
        RapidModule m = RapidParser.parse("MODULE M\n  LOCAL CONST zonedata zCorner := z10;\n  VAR speeddata vMove := v300;\nENDMODULE\n", "m");
        assertEquals(ZoneData.predefined("z10").orElseThrow(), m.declaration("zCorner").orElseThrow().value());
        InputException e = assertThrows(InputException.class,
                () -> RapidParser.parse("MODULE M\n  CONST zonedata zC := v100;\nENDMODULE\n", "m"));
        assertEquals(2, e.line());
        assertEquals(24, e.column());
    }

    @Test
    void parse_localProc_keptLocalInModelAndExport() {
        RapidModule m = RapidParser.parse("MODULE M\n  LOCAL PROC helper()\n    WaitTime 1;\n  ENDPROC\nENDMODULE\n", "m");
        assertTrue(m.procedure("helper").orElseThrow().local());
        assertTrue(RapidWriter.export(m).text().contains("  LOCAL PROC helper()\n"));
    }

    @Test
    void parse_caseInsensitiveKeywords_accepted() {
        RapidModule m = RapidParser.parse("module m\n  const num a:=1;\n  proc main()\n    waittime 2;\n  endproc\nendmodule\n", "m");
        assertEquals(List.of("main"), m.procedures().stream().map(Procedure::name).toList());
    }
}
