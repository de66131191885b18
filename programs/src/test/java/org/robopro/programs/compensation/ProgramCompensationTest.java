package org.robopro.programs.compensation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robopro.calibration.compensation.Compensator;
import org.robopro.calibration.compensation.TargetCompensator.Status;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;

class ProgramCompensationTest {

    @Test
    void compensate_perturbedRobot_calibratedRobotReachesIntendedTargetsFromExportedFile() {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        KinematicModel real = WorldCalibration.of(7).calibrated();
        ToolData torch = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.15), Quaternion.IDENTITY), LoadData.LOAD0);
        WObjData table = new WObjData(false, true, "", new RapidPose(new Vec3(0.9, -0.2, 0.5), Quaternion.IDENTITY), RapidPose.IDENTITY);
        RobTarget a = Teach.taught(nominal, new double[] {0.3, 0.2, 0.1, 0.2, 0.7, -0.3}, torch, table);
        RobTarget b = Teach.taught(nominal, new double[] {0.1, 0.3, 0.0, 0.1, 0.6, -0.1}, torch, table);
        RapidModule m = RapidModule.builder("C").pers("tTorch", torch).pers("wTable", table).constant("pA", a)
                .procedure("main", List.of(Move.moveJ(Ref.to("pA"), Ref.to("v1000"), Ref.to("fine"), "tTorch", "wTable"),
                        Move.moveL(Ref.inline(b), Ref.to("v100"), Ref.to("fine"), "tTorch", "wTable"))).build();
        ProgramCompensation.Outcome out = ProgramCompensation.compensate(m, "main", nominal, new Compensator(nominal, real, Pose.IDENTITY, Pose.IDENTITY));
        assertEquals(2, out.corrections().size());
        for (ProgramCompensation.Correction c : out.corrections()) {
            assertEquals(Optional.of(Status.CONVERGED), c.status(), c.toString());
            assertTrue(c.shiftM() > 1e-4, "the perturbation needs a visible correction: " + c);
        }
        String text = RapidWriter.export(out.module()).text();
        List<MoveStep> intended = MotionInterpreter.of(m).moves("main");
        List<MoveStep> commanded = MotionInterpreter.of(RapidParser.parse(text, "C.mod")).moves("main");
        InverseKinematics ik = InverseKinematics.of(nominal);
        for (int k = 0; k < 2; k++) {
            MoveStep cs = commanded.get(k);
            double[] q = ik.solveWithConf(cs.baseTflange().orElseThrow(), cs.conf().orElseThrow()).orElseThrow().q();
            Pose reached = real.flange(q).times(cs.flangeTtcp());
            assertEquals(0, reached.distanceTo(intended.get(k).baseTtcp().orElseThrow()), 2e-6, "file precision 1e-6 mm, quaternion 1e-10");
            assertEquals(0, reached.angleTo(intended.get(k).baseTtcp().orElseThrow()), 1e-6);
        }
    }

    @Test
    void compensate_moveC_circlePointsNamedAndInlineReachedByRealRobot() {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        KinematicModel real = WorldCalibration.of(11).calibrated();
        ToolData torch = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.15), Quaternion.IDENTITY), LoadData.LOAD0);
        WObjData table = new WObjData(false, true, "", new RapidPose(new Vec3(0.9, -0.2, 0.5), Quaternion.IDENTITY), RapidPose.IDENTITY);
        RobTarget start = Teach.taught(nominal, new double[] {0.1, 0.2, 0.1, 0.2, 0.7, -0.3}, torch, table);
        RobTarget via = Teach.taught(nominal, new double[] {0.2, 0.25, 0.05, 0.2, 0.7, -0.3}, torch, table);
        RobTarget end = Teach.taught(nominal, new double[] {0.3, 0.2, 0.1, 0.2, 0.7, -0.3}, torch, table);
        RobTarget via2 = Teach.taught(nominal, new double[] {0.2, 0.15, 0.15, 0.2, 0.7, -0.3}, torch, table);
        RapidModule m = RapidModule.builder("C").pers("tTorch", torch).pers("wTable", table)
                .constant("pStart", start).constant("pVia", via).constant("pEnd", end)
                .procedure("main", List.of(Move.moveJ(Ref.to("pStart"), Ref.to("v1000"), Ref.to("fine"), "tTorch", "wTable"),
                        Move.moveC(Ref.to("pVia"), Ref.to("pEnd"), Ref.to("v100"), Ref.to("fine"), "tTorch", "wTable"),
                        Move.moveC(Ref.inline(via2), Ref.to("pStart"), Ref.to("v100"), Ref.to("fine"), "tTorch", "wTable"))).build();
        ProgramCompensation.Outcome out = ProgramCompensation.compensate(m, "main", nominal, new Compensator(nominal, real, Pose.IDENTITY, Pose.IDENTITY));
        // pStart, pVia, pEnd by name, and the inline circle point of the second MoveC.
        assertEquals(4, out.corrections().size(), out.corrections().toString());
        for (ProgramCompensation.Correction c : out.corrections()) assertEquals(Optional.of(Status.CONVERGED), c.status(), c.toString());
        String text = RapidWriter.export(out.module()).text();
        List<MoveStep> intended = MotionInterpreter.of(m).moves("main");
        List<MoveStep> commanded = MotionInterpreter.of(RapidParser.parse(text, "C.mod")).moves("main");
        InverseKinematics ik = InverseKinematics.of(nominal);
        // The controller reaches each commanded circle point on the branch it was taught on.
        double[][] taught = {null, {0.2, 0.25, 0.05, 0.2, 0.7, -0.3}, {0.2, 0.15, 0.15, 0.2, 0.7, -0.3}};
        for (int k = 1; k <= 2; k++) {
            MoveStep cs = commanded.get(k);
            Pose cmdCirc = cs.baseTflangeCirc().orElseThrow();
            double[] q = ik.solveNear(cmdCirc, taught[k]).orElseThrow().q();
            Pose reached = real.flange(q).times(cs.flangeTtcp());
            Pose wanted = intended.get(k).baseTtcpCirc().orElseThrow();
            assertTrue(wanted.distanceTo(cs.baseTtcpCirc().orElseThrow()) > 1e-4, "the circle point must have moved");
            assertEquals(0, reached.distanceTo(wanted), 2e-6, "circle point of MoveC " + k);
        }
    }

    @Test
    void compensate_targetsItCannotRewrite_namedNotPassedOverSilently() {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        String text = "MODULE M\n"
                + "  CONST robtarget p1:=[[900,0,900],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];\n"
                + "  PROC main()\n"
                + "    MoveJ p1, v1000, fine, tool0;\n"
                + "    FOR i FROM 1 TO 2 DO\n"
                + "      MoveL Offs(p1, 0, 20 * i, 0), v100, fine, tool0;\n"
                + "    ENDFOR\n"
                + "    IF TRUE THEN\n"
                + "      MoveL [[900,50,850],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]], v100, fine, tool0;\n"
                + "    ENDIF\n"
                + "  ENDPROC\n"
                + "ENDMODULE\n";
        ProgramCompensation.Outcome out = ProgramCompensation.compensate(RapidParser.parse(text, "M.mod"), "main", nominal,
                new Compensator(nominal, nominal, Pose.IDENTITY, Pose.IDENTITY));
        List<ProgramCompensation.Correction> not = out.corrections().stream().filter(c -> c.status().isEmpty()).toList();
        assertEquals(2, not.size(), out.corrections().toString());
        assertTrue(not.get(0).target().startsWith("Offs(p1") && not.get(0).notCompensated().contains("main#2[i=1] > main#1"), not.toString());
        assertTrue(not.get(1).notCompensated().contains("inline target") && not.get(1).target().startsWith("main#3 > main#1"), not.toString());
        assertTrue(out.corrections().stream().anyMatch(c -> c.target().equals("p1") && c.ok()), out.corrections().toString());
    }

    @Test
    void compensate_inlineTargetsOfCalledAndUncalledProcedures_rewrittenWhereTheyRun() {
        KinematicModel nominal = KinematicModel.build(RobotLibrary.shipped("irb2000"));
        KinematicModel real = WorldCalibration.of(11).calibrated();
        String inline = "[[900,50,850],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]";
        String text = "MODULE M\n"
                + "  CONST robtarget p1:=[[900,0,900],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];\n"
                + "  PROC main()\n    MoveJ p1, v1000, fine, tool0;\n    seam;\n  ENDPROC\n"
                + "  PROC seam()\n    MoveL " + inline + ", v100, fine, tool0;\n  ENDPROC\n"
                + "  PROC spare()\n    MoveL " + inline + ", v100, fine, tool0;\n  ENDPROC\n"
                + "ENDMODULE\n";
        ProgramCompensation.Outcome out = ProgramCompensation.compensate(RapidParser.parse(text, "M.mod"), "main", nominal,
                new Compensator(nominal, real, Pose.IDENTITY, Pose.IDENTITY));
        // Every target is compensated; none is listed as left alone (the called procedure's inline target is rewritten).
        assertEquals(List.of("p1", "seam#1 *", "spare#1 *"), out.corrections().stream().map(ProgramCompensation.Correction::target).toList());
        assertTrue(out.corrections().stream().allMatch(ProgramCompensation.Correction::ok), out.corrections().toString());
        // The real robot reaches the intended inline pose when commanded the compensated one.
        Pose wanted = MotionInterpreter.of(RapidParser.parse(text, "M.mod")).moves("seam").get(0).baseTtcp().orElseThrow();
        MoveStep commanded = MotionInterpreter.of(out.module()).moves("seam").get(0);
        double[] q = InverseKinematics.of(nominal).solveWithConf(commanded.baseTflange().orElseThrow(), commanded.conf().orElseThrow())
                .orElseThrow().q();
        assertTrue(commanded.baseTtcp().orElseThrow().distanceTo(wanted) > 1e-4, "the perturbation needs a visible correction");
        assertEquals(0, real.flange(q).times(commanded.flangeTtcp()).distanceTo(wanted), 2e-6);
    }

    /**
     * The end-to-end claim on the independent truth: a program taught on the nominal model,
     * compensated with the calibration of a world robot, exported and read back, makes the world's
     * robot put its tool where the program meant, within the measuring noise; uncompensated it
     * misses by millimetres. The program's tool is the measured target, so the compensation gives
     * it the calibrated tool.
     */
    @Test
    void compensate_worldRobot_reachesTheIntendedPointsWithinTheNoise() {
        KinematicModel nominal = KinematicModel.build(WorldCalibration.IRB2000);
        WorldCalibration wc = WorldCalibration.of(17);
        ToolData smr = new ToolData(true, new RapidPose(new Vec3(0, 0, 0.1), Quaternion.IDENTITY), LoadData.LOAD0);
        WObjData table = new WObjData(false, true, "", new RapidPose(new Vec3(0.9, -0.2, 0.5), Quaternion.IDENTITY), RapidPose.IDENTITY);
        double[][] taught = {{0.3, 0.2, 0.1, 0.2, 0.7, -0.3}, {0.1, 0.3, 0.0, 0.1, 0.6, -0.1}, {-0.4, 0.1, 0.2, -0.3, 0.8, 0.5},
                {0.6, -0.1, 0.3, 0.5, -0.7, 0.2}, {-0.2, 0.4, -0.2, 0.0, 0.9, -0.6}, {0.0, 0.0, 0.4, 0.7, 0.5, 1.0}};
        RapidModule.Builder b = RapidModule.builder("W").pers("tSmr", smr).pers("wTable", table);
        List<org.robopro.programs.Statement> moves = new java.util.ArrayList<>();
        for (int k = 0; k < taught.length; k++) {
            b.constant("p" + k, Teach.taught(nominal, taught[k], smr, table));
            moves.add(Move.moveL(Ref.to("p" + k), Ref.to("v100"), Ref.to("fine"), "tSmr", "wTable"));
        }
        RapidModule m = b.procedure("main", moves).build();
        ProgramCompensation.Outcome out = ProgramCompensation.compensate(m, "main", nominal,
                new Compensator(nominal, wc.calibrated(), WorldCalibration.nominalTarget(), wc.result().flangeTtool()));
        for (ProgramCompensation.Correction c : out.corrections()) assertEquals(Optional.of(Status.CONVERGED), c.status(), c.toString());
        List<MoveStep> intended = MotionInterpreter.of(m).moves("main");
        List<MoveStep> commanded = MotionInterpreter.of(RapidParser.parse(RapidWriter.export(out.module()).text(), "W.mod")).moves("main");
        InverseKinematics ik = InverseKinematics.of(nominal);
        double before = 0, after = 0;
        for (int k = 0; k < taught.length; k++) {
            Vec3 wanted = intended.get(k).baseTtcp().orElseThrow().position();
            // The controller turns each target into joints with the nominal model, as it always does.
            double[] qPlain = ik.solveWithConf(intended.get(k).baseTflange().orElseThrow(), intended.get(k).conf().orElseThrow()).orElseThrow().q();
            double[] qComp = ik.solveWithConf(commanded.get(k).baseTflange().orElseThrow(), commanded.get(k).conf().orElseThrow()).orElseThrow().q();
            before += Math.pow(new Vec3(wc.truePoint(qPlain)[0], wc.truePoint(qPlain)[1], wc.truePoint(qPlain)[2]).minus(wanted).norm(), 2);
            after += Math.pow(new Vec3(wc.truePoint(qComp)[0], wc.truePoint(qComp)[1], wc.truePoint(qComp)[2]).minus(wanted).norm(), 2);
        }
        before = Math.sqrt(before / taught.length);
        after = Math.sqrt(after / taught.length);
        System.out.printf("program on the world robot: %.3f mm uncompensated, %.4f mm compensated (floor %.4f mm)%n", before * 1e3,
                after * 1e3, wc.floorM() * 1e3);
        assertTrue(before > 1e-3, "uncompensated the world robot should miss by millimetres: " + before);
        assertTrue(after < wc.floorM(), "compensated RMS " + after * 1e3 + " mm");
    }
}
