package org.robopro.programs.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.models.Vec3;
import org.robopro.programs.RapidParser;

class ControlFlowTest {

    static Simulation sim(String text, int max) {
        return MotionInterpreter.of(RapidParser.parseDetailed(text, "c.mod")).withMaxStatements(max).simulate("main");
    }

    @Test
    void simulate_palletFixture_movesAtGridPointsInOrder() {
        String text;
        try (java.io.InputStream in = ControlFlowTest.class.getResourceAsStream("/org/robopro/programs/rapid/Palletize.mod")) {
            text = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            throw new IllegalStateException(e);
        }
        Simulation s = MotionInterpreter.of(RapidParser.parseDetailed(text, "Palletize.mod")).simulate("main");
        List<MoveStep> moves = s.steps().stream().filter(x -> x instanceof MoveStep).map(x -> (MoveStep) x).toList();
        // home + 6 places x 3 moves + the final move of the TEST (nDone = 6, 6 MOD 2 = 0: CRobT then Offs)
        assertEquals(1 + 18 + 1, moves.size());
        // place 2,3: pBase + ((2-1)*50, (3-1)*40, 0) mm; tool z down, so the TCP is at that point.
        Vec3 tcp = moves.get(1 + 5 * 3 + 1).baseTtcp().orElseThrow().position();
        assertEquals(0, tcp.minus(new Vec3(0.650, -0.120, 0.100)).norm(), 1e-9);
        // RelTool 0,0,-30 in a tool frame pointing down: 30 mm above.
        Vec3 above = moves.get(1 + 5 * 3).baseTtcp().orElseThrow().position();
        assertEquals(0, above.minus(new Vec3(0.650, -0.120, 0.130)).norm(), 1e-9);
        // last: CRobT (the last place's RelTool target) lowered by -(50-10)*2 = -80 mm
        Vec3 last = moves.get(moves.size() - 1).baseTtcp().orElseThrow().position();
        assertEquals(0, last.minus(new Vec3(0.650, -0.120, 0.130 - 0.080)).norm(), 1e-9);
        assertTrue(s.log().get(0).startsWith("TPWrite \"done 6\""), s.log().toString());
    }

    @Test
    void simulate_cellServer_socketsNotSimulatedServerLoopStopsWithPosition() {
        String text;
        try (java.io.InputStream in = ControlFlowTest.class.getResourceAsStream("/org/robopro/programs/rapid/CellServer.mod")) {
            text = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            throw new IllegalStateException(e);
        }
        MotionInterpreter it = MotionInterpreter.of(RapidParser.parseDetailed(text, "CellServer.mod"));
        // without a start position, CJointT() before any move is unknown
        InputException noStart = assertThrows(InputException.class, () -> it.simulate("main"));
        assertTrue(noStart.getMessage().contains("CJointT"), noStart.getMessage());
        // Socket instructions are kept and passed over (each reported once); the server's WHILE TRUE is bounded.
        InputException e = assertThrows(InputException.class,
                () -> it.withStartJoints(org.robopro.programs.JointTarget.of(0, 0, 0, 0, 0, 0)).withMaxStatements(2000).simulate("main"));
        assertTrue(e.getMessage().contains("stopped after 2000 statements") && e.getMessage().contains("loop at 38:5"), e.getMessage());
    }

    @Test
    void simulate_waitUntilFalse_recordedAsAWaitInsteadOfWaitingForever() {
        String text = "MODULE M\n  VAR bool ready;\n  PROC main()\n    WaitUntil ready;\n  ENDPROC\nENDMODULE\n";
        IoStep w = (IoStep) sim(text, 100).steps().get(0);
        assertEquals(IoStep.Kind.WAIT_CONDITION, w.kind());
        assertEquals("ready", w.text());
        assertEquals(4, w.source().orElseThrow().line());
        Simulation ok = sim(text.replace("VAR bool ready;", "VAR bool ready := TRUE;"), 100);
        assertTrue(ok.log().get(0).startsWith("WaitUntil"), ok.log().toString());
    }

    @Test
    void simulate_whileTrue_stopsWithLoopPosition() {
        String text = "MODULE M\n  PROC main()\n    WHILE TRUE DO\n      WaitTime 1;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n";
        InputException e = assertThrows(InputException.class, () -> sim(text, 1000));
        assertTrue(e.getMessage().contains("stopped after 1000 statements"), e.getMessage());
        assertTrue(e.getMessage().contains("loop at 3:5"), e.getMessage());
    }

    @Test
    void simulate_ioInstructions_recordedWithPositionUnknownOnesNoticedOnce() {
        String text = "MODULE M\n  PROC main()\n    MoveL Offs([[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],0,0,1), v100, z10, tool0;\n    SetDO do1, 1;\n  ENDPROC\nENDMODULE\n";
        Simulation s = sim(text, 1000);
        IoStep set = (IoStep) s.steps().get(1);
        assertEquals(IoStep.Kind.SET, set.kind());
        assertEquals("do1", set.signal());
        assertEquals(1.0, set.value(), 0);
        assertEquals(4, set.source().orElseThrow().line());
        String twice = text.replace("SetDO do1, 1;", "FOR i FROM 1 TO 3 DO\n      SpotL p, v100, gun1, tool0;\n    ENDFOR");
        Simulation u = sim(twice, 1000);
        assertEquals(1, u.notices().size(), u.notices().toString());
        assertTrue(u.notices().get(0).message().contains("not simulated: SpotL at 5:7"), u.notices().toString());
    }

    @Test
    void simulate_forStepAndProcArguments_countsAndInout() {
        String text = "MODULE M\n  VAR num n:=0;\n  PROC main()\n    FOR i FROM 10 TO 1 STEP -3 DO\n      add2 n;\n    ENDFOR\n"
                + "    IF n <> 8 RAISE;\n  ENDPROC\n  PROC add2(INOUT num x)\n    x := x + 2;\n  ENDPROC\nENDMODULE\n";
        assertEquals(0, sim(text, 1000).steps().size());
        String wrong = text.replace("n <> 8", "n <> 6");
        InputException e = assertThrows(InputException.class, () -> sim(wrong, 1000));
        assertTrue(e.getMessage().contains("not simulated: RAISE"), e.getMessage());
    }

    @Test
    void simulate_waitAndIoSteps_pointToTheirStatementNodes() {
        String text = "MODULE M\n  PROC main()\n    WaitTime 0.5;\n    SetDO do1, 1;\n    FOR i FROM 1 TO 2 DO\n      WaitTime 0.25;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
        org.robopro.programs.ParsedModule pm = RapidParser.parseDetailed(text, "w.mod");
        Simulation s = MotionInterpreter.of(pm).simulate("main");
        var body = ((org.robopro.programs.rapid.RapidAst.Routine) pm.ast().module().items().get(0)).body();
        assertEquals(4, s.steps().size(), s.steps().toString());
        assertTrue(((WaitStep) s.steps().get(0)).statement().orElseThrow() == body.get(0), "WaitTime 0.5 is statement 1");
        assertTrue(((IoStep) s.steps().get(1)).statement().orElseThrow() == body.get(1), "SetDO is statement 2");
        var loop = (org.robopro.programs.rapid.RapidAst.For) body.get(2);
        // One statement run twice: two steps, the same node.
        assertTrue(((WaitStep) s.steps().get(2)).statement().orElseThrow() == loop.body().get(0));
        assertTrue(((WaitStep) s.steps().get(3)).statement().orElseThrow() == loop.body().get(0));
    }

    @Test
    void simulate_stringEscapes_resolvedAsTheParserDoesAndBadOnesRefused() {
        String text = "MODULE M\n  CONST string s := \"a\\\\b\\22c\";\n  PROC main()\n    TPWrite \"x\\41\" + s;\n  ENDPROC\nENDMODULE\n";
        Simulation s = sim(text, 100);
        assertTrue(s.log().get(0).startsWith("TPWrite \"xAa\\b\"c\""), s.log().toString());
        String bad = "MODULE M\n  VAR string t;\n  PROC main()\n    t := \"x\\q\";\n  ENDPROC\nENDMODULE\n";
        InputException e = assertThrows(InputException.class, () -> sim(bad, 100));
        assertTrue(e.getMessage().contains("bad escape") && e.getMessage().contains("4:"), e.getMessage());
    }
}
