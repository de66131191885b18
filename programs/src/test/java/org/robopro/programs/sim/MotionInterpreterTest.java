package org.robopro.programs.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;
import org.robopro.models.Vec3;
import org.robopro.kinematics.ConfData;
import org.robopro.programs.Move;
import org.robopro.programs.RapidModule;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ZoneData;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.RapidParser;

class MotionInterpreterTest {

    static String fixture() {
        try (InputStream in = MotionInterpreterTest.class.getResourceAsStream("/org/robopro/programs/rapid/PickPlace.mod")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void run_fixture_stepsInCallOrderWithBasePoses() {
        ParsedModule pm = RapidParser.parseDetailed(fixture(), "PickPlace.mod");
        List<ProgramStep> steps = MotionInterpreter.of(pm).run();
        List<String> labels = steps.stream().map(ProgramStep::label).toList();
        assertEquals(List.of("main#1 MoveAbsJ jHome", "main#2 > pick#1 MoveJ pPickAbove", "main#2 > pick#3 MoveL pPick", "main#2 > pick#4 WaitTime",
                "main#2 > pick#5 MoveL pPickAbove", "main#4 MoveC *", "main#5 MoveL *", "main#6 WaitTime", "main#7 MoveAbsJ jHome"), labels);
        MoveStep pick = (MoveStep) steps.get(2);
        // wobjConveyor: user frame at (800,-200,400) mm turned 90 deg about z; pPick (100,50,20) mm in it.
        Vec3 tcp = pick.baseTtcp().orElseThrow().position();
        assertEquals(0, tcp.minus(new Vec3(0.750, -0.100, 0.420)).norm(), 1e-12);
        // Tool z points down (q = [0,0,1,0]); the flange is 150 mm above the TCP.
        Vec3 flange = pick.baseTflange().orElseThrow().position();
        assertEquals(0, flange.minus(new Vec3(0.750, -0.100, 0.570)).norm(), 1e-12);
        Pose check = pick.baseTflange().orElseThrow().times(pick.flangeTtcp());
        assertEquals(0, check.distanceTo(pick.baseTtcp().orElseThrow()), 1e-12);
        assertEquals(0.0, pick.zone().pzoneTcp());
        assertTrue(pick.zone().finep());
        assertEquals(36, pick.source().orElseThrow().line(), "pick's 3rd statement");
        MoveStep slow = (MoveStep) steps.get(6);
        assertEquals(0.080, slow.speed().vTcp(), 1e-15);
        MoveStep home = (MoveStep) steps.get(0);
        assertEquals(Move.Kind.MOVE_ABS_J, home.kind());
        assertEquals(Math.toRadians(30), home.q().orElseThrow()[4], 1e-15);
        assertInstanceOf(WaitStep.class, steps.get(3));
        assertEquals(0.2, ((WaitStep) steps.get(3)).seconds());
    }

    @Test
    void run_moduleBuiltInCode_exactValuesAndNamesAsGiven() {
        // More digits than a file keeps (1e-9 m), and a name RAPID would not take (export renames it).
        Pose objTtcp = Pose.translation(0.123456789012345, -0.3333333333333333, 0.7071067811865476).times(Pose.rotY(0.1));
        RobTarget t = RobTarget.of(objTtcp, new ConfData(0, 0, 0, 0));
        RapidModule m = RapidModule.builder("Built").constant("p target", t)
                .procedure("main", List.of(Move.moveL(Ref.to("p target"), Ref.to("v100"), Ref.to("z10"), "tool0", null),
                        Move.moveL(Ref.inline(t), Ref.inline(SpeedData.ofRapid(123.4567891234, 500, 5000, 1000)), Ref.to("fine"), "tool0", null)))
                .build();
        List<MoveStep> moves = MotionInterpreter.of(m).moves("main");
        assertEquals("main#1 MoveL p target", moves.get(0).label());
        for (MoveStep mv : moves) {
            Pose tcp = mv.baseTtcp().orElseThrow();
            assertEquals(0, tcp.distanceTo(t.pose()), 1e-15);
            assertEquals(0, tcp.angleTo(t.pose()), 1e-15);
        }
        assertEquals(0.1234567891234, moves.get(1).speed().vTcp(), 1e-16);
        assertEquals(ZoneData.FINE, moves.get(1).zone());
    }

    @Test
    void run_unknownTarget_inputExceptionWithPosition() {
        String text = "MODULE M\n  PROC main()\n    MoveL pNowhere, v100, z10, tool0;\n  ENDPROC\nENDMODULE\n";
        InputException e = assertThrows(InputException.class, () -> MotionInterpreter.of(RapidParser.parseDetailed(text, "m.mod")).run());
        assertEquals(3, e.line());
        assertEquals(5, e.column());
        assertTrue(e.getMessage().contains("unknown robtarget 'pNowhere'"), e.getMessage());
    }

    @Test
    void run_recursiveCall_refusedClearly() {
        String text = "MODULE M\n  PROC main()\n    again;\n  ENDPROC\n  PROC again()\n    again;\n  ENDPROC\nENDMODULE\n";
        InputException e = assertThrows(InputException.class, () -> MotionInterpreter.of(RapidParser.parseDetailed(text, "m.mod")).run());
        assertTrue(e.getMessage().contains("recursion"), e.getMessage());
        assertEquals(6, e.line());
    }
}
