package org.robopro.programs.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.KinematicModel;
import org.robopro.models.InputException;
import org.robopro.models.RobotLibrary;
import org.robopro.programs.RapidParser;
import org.robopro.programs.sim.MotionInterpreter;

/** Work bounded by the robot's reach and the input's size: far targets and deep expressions fail fast and located. */
class BoundedWorkTest {
    static final KinematicModel IRB2000 = KinematicModel.build(RobotLibrary.shipped("irb2000"));

    static String far(String x) {
        return "MODULE Far\n"
                + "  CONST robtarget pNear:=[[900,0,900],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];\n"
                + "  CONST robtarget pFar:=[[" + x + ",0,900],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];\n"
                + "  PROC main()\n"
                + "    MoveJ pNear, v1000, fine, tool0;\n"
                + "    MoveL pFar, v1000, fine, tool0;\n"
                + "    MoveC pNear, pFar, v1000, fine, tool0;\n"
                + "  ENDPROC\n"
                + "ENDMODULE\n";
    }

    @Test
    void reach_boundsEveryShippedRobotsFlangeAtRandomJoints() {
        for (String name : RobotLibrary.shippedNames()) {
            KinematicModel m = KinematicModel.build(RobotLibrary.shipped(name));
            double reach = PathChecker.reach(m), max = 0;
            for (double[] q : m.randomConfigurations(5000, 11)) max = Math.max(max, m.flange(q).position().norm());
            assertTrue(max <= reach + 1e-12, name + ": flange at " + max + " m beyond the bound " + reach);
            assertTrue(reach < 3 * max, name + ": the bound " + reach + " m is no use (max seen " + max + " m)");
        }
    }

    @Test
    void check_farTargets_unreachableWithinMilliseconds() {
        for (String x : new String[] {"1E+06", "1E+07", "1E+300"}) {
            CheckReport r = assertTimeoutPreemptively(Duration.ofSeconds(2), () -> new PathChecker(IRB2000)
                    .check(MotionInterpreter.of(RapidParser.parseDetailed(far(x), "Far.mod")).run()), x);
            assertTrue(r.hasErrors(), r::format);
            Problem p = r.problems().stream().filter(q -> q.kind() == Problem.Kind.UNREACHABLE).findFirst().orElseThrow();
            assertEquals(6, p.source().orElseThrow().line(), r::format);
            assertTrue(p.message().contains("reach"), p.message());
        }
    }

    static String sum(int terms) {
        StringBuilder sum = new StringBuilder("1");
        for (int k = 1; k < terms; k++) sum.append("+1");
        return "MODULE Sum\n  VAR num n:=0;\n  PROC main()\n    n:=" + sum + ";\n    WaitTime n/1000;\n  ENDPROC\nENDMODULE\n";
    }

    @Test
    void simulate_longSums_evaluatedWithinTheBoundLocatedErrorBeyond() {
        // 1000 terms (999 operators): evaluated; the wait is n / 1000 s.
        var s = MotionInterpreter.of(RapidParser.parseDetailed(sum(1000), "Sum.mod")).simulate("main");
        assertEquals(1.0, ((org.robopro.programs.sim.WaitStep) s.steps().get(0)).seconds(), 1e-12);
        for (int terms : new int[] {5000, 200_000}) {
            InputException e = assertThrows(InputException.class, () -> RapidParser.parseDetailed(sum(terms), "Sum.mod"));
            assertEquals(4, e.line(), e.getMessage());
            assertTrue(e.getMessage().contains("Sum.mod") && e.getMessage().contains("operators"), e.getMessage());
        }
    }
}
