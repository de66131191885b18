package org.robopro.programs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.check.Problem;
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

    /**
     * Targets taught with axes 1, 4, 6 on quadrant boundaries (0, +-90 deg, -0.0, and the few
     * 1e-15 rad a Cartesian jog leaves there), exported to RAPID, read back and checked: each is
     * reached in the configuration it was taught in (MoveJ), and a MoveL back to it ends in it.
     */
    @Test
    void taughtOnQuadrantBoundaries_exportedImportedChecked_reachedInItsOwnConfiguration() {
        InverseKinematics ik = InverseKinematics.of(IRB2000);
        ToolData torch = new ToolData(true, new RapidPose(new Vec3(0.11, 0, 0.34), new Quaternion(0.9537169507, 0, 0.3007057995, 0)),
                LoadData.LOAD0);
        double d = Math.PI / 180;
        double[][] taught = {
                {10 * d, 29.862 * d, 8.393 * d, -6.254e-15, 56.607 * d, 0}, // the workbench's ready pose jogged, then taught
                {0, 25 * d, 5 * d, 0, 60 * d, 0},                            // the ready pose itself
                {-0.0, 25 * d, 5 * d, -0.0, 60 * d, -0.0},
                {1e-15, 20 * d, 10 * d, 2e-15, 50 * d, -3e-15},
                {30 * d, 15 * d, 0, 90 * d, 45 * d, -90 * d},
                {-30 * d, 35 * d, 5 * d, -90 * d, 70 * d, 180 * d}};
        int k = 0;
        for (double[] q : taught) {
            RobTarget a = Teach.taught(IRB2000, q, torch, WObjData.WOBJ0);
            double[] q2 = q.clone();
            q2[1] += 3 * d;
            q2[4] -= 4 * d;
            RobTarget b = Teach.taught(IRB2000, q2, torch, WObjData.WOBJ0);
            RapidModule module = RapidModule.builder("Boundary").pers("tTorch", torch).constant("pA", a).constant("pB", b)
                    .procedure("main", List.of(
                            Move.moveJ(Ref.to("pA"), Ref.to("v500"), Ref.to("z10"), "tTorch", null),
                            Move.moveL(Ref.to("pB"), Ref.to("v500"), Ref.to("z10"), "tTorch", null),
                            Move.moveL(Ref.to("pA"), Ref.to("v500"), Ref.to("fine"), "tTorch", null)))
                    .build();
            String text = RapidWriter.export(module).text();
            RapidChecker.assertValid("Boundary" + k + ".mod", text);
            ParsedModule back = RapidParser.parseDetailed(text, "Boundary" + k++ + ".mod");
            ConfData written = back.module().declaration("pA").map(x -> ((RobTarget) x.value()).robconf()).orElseThrow();
            assertEquals(ik.confOf(q), written, "the exported confdata is the taught joints'");
            CheckReport r = new PathChecker(IRB2000).check(MotionInterpreter.of(back).run());
            String where = "taught at " + java.util.Arrays.toString(q) + " in " + written + ":\n" + r.format();
            assertFalse(r.hasErrors(), where);
            assertTrue(r.problems().stream().noneMatch(p -> p.kind() == Problem.Kind.CONFIGURATION_MISMATCH), where);
            for (int j = 0; j < 6; j++) {
                assertEquals(q[j], r.steps().get(0).qEnd()[j], 1e-6, "MoveJ reaches the taught joint " + (j + 1) + "; " + where);
                assertEquals(q[j], r.steps().get(2).qEnd()[j], 1e-6, "MoveL back ends at the taught joint " + (j + 1) + "; " + where);
            }
        }
    }
}
