package org.robopro.programs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.rapid.RapidChecker;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;

class TeachTest {
    static final KinematicModel IRB2000 = KinematicModel.build(RobotLibrary.shipped("irb2000"));

    @Test
    void seam_twoPassesExported_everyTargetReachedByFkWithItsConfAndRapidcheckerAccepts() {
        InverseKinematics ik = InverseKinematics.of(IRB2000);
        ToolData torch = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.15), Quaternion.IDENTITY), LoadData.LOAD0);
        WObjData table = new WObjData(false, true, "", new RapidPose(new Vec3(0.9, -0.2, 0.5), Quaternion.IDENTITY), RapidPose.IDENTITY);
        Teach.Seam seam = new Teach.Seam(new Vec3(0, 0, 0), new Vec3(0, 0.4, 0), new Vec3(0, 0, 1), Math.toRadians(15),
                Math.toRadians(10), List.of(new double[] {0, 0}, new double[] {0.004, 0.003}), 0.05);
        Teach.SeamTargets st = Teach.seam(ik, seam, torch, table, new double[] {0, 0.3, 0.2, 0, 1.0, 0}, "pSeam");
        RapidModule.Builder b = RapidModule.builder("Seam").pers("tTorch", torch).pers("wTable", table);
        List<Statement> body = new ArrayList<>();
        for (int k = 0; k < st.names().size(); k++) {
            b.constant(st.names().get(k), st.targets().get(k));
            body.add(Move.moveL(Ref.to(st.names().get(k)), Ref.to(k % 4 == 2 ? "v20" : "v200"), Ref.to("fine"), "tTorch", "wTable"));
        }
        String text = RapidWriter.export(b.procedure("main", body).build()).text();
        RapidChecker.assertValid("Seam.mod", text);
        List<MoveStep> steps = MotionInterpreter.of(RapidParser.parseDetailed(text, "Seam.mod")).moves("main");
        assertEquals(8, steps.size());
        for (MoveStep s : steps) {
            IkSolution sol = ik.solveWithConf(s.baseTflange().orElseThrow(), s.conf().orElseThrow()).orElseThrow();
            Pose reached = IRB2000.flange(sol.q()).times(s.flangeTtcp());
            assertEquals(0, reached.distanceTo(s.baseTtcp().orElseThrow()), 1e-6, s.label());
            assertEquals(0, reached.angleTo(s.baseTtcp().orElseThrow()), 1e-6, s.label());
        }
        // The torch leans by the work angle from the surface normal (no travel tilt about x).
        Pose start = steps.get(1).baseTtcp().orElseThrow();
        double tilt = Math.acos(-start.zAxis().z());
        assertEquals(Math.hypot(15, 10), Math.toDegrees(tilt), 0.5);
        CheckReport r = new PathChecker(IRB2000).check(MotionInterpreter.of(RapidParser.parseDetailed(text, "Seam.mod")).run());
        assertFalse(r.hasErrors(), r::format);
    }
}
