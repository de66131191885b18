package org.robopro.comms.sim;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.MotionResult;
import org.robopro.comms.protocol.Checksums;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

class SimulatedControllerTest {

    static SimulatedController controller(double noiseM) {
        return new SimulatedController(new GantryRobot(noiseM), SimulatedController.Settings.defaults(7));
    }

    @Test
    void moveJoints_withinLimits_reachesTargetInJointLimitedTime() {
        SimulatedController c = controller(0);
        Random rnd = new Random(1);
        GantryRobot robot = new GantryRobot();
        for (int k = 0; k < 20; k++) {
            double[] from = c.readJoints();
            double[] to = new double[6];
            for (int i = 0; i < 6; i++) to[i] = robot.lowerLimits()[i] + rnd.nextDouble() * (robot.upperLimits()[i] - robot.lowerLimits()[i]);
            double slowest = 0;
            for (int i = 0; i < 6; i++) slowest = Math.max(slowest, Math.abs(to[i] - from[i]) / robot.maxSpeeds()[i]);
            MotionResult r = c.moveJoints(0, to);
            assertArrayEquals(to, c.readJoints(), 0);
            assertTrue(r.motionTimeS() >= slowest - 1e-12, "motion faster than the joint speed limits allow");
        }
    }

    @Test
    void moveJoints_outsideLimits_refusedAndRobotStays() {
        SimulatedController c = controller(0);
        double[] before = c.readJoints();
        CommsException.Refused e = assertThrows(CommsException.Refused.class,
                () -> c.moveJoints(0, new double[] {0, 0, 0, 0, 1.5, 0}));
        assertEquals(ErrorCode.JOINT_LIMIT, e.code());
        assertTrue(e.getMessage().contains("joint 5"), e.getMessage());
        assertArrayEquals(before, c.readJoints(), 0);
        assertEquals(0, c.motionsExecuted());
    }

    @Test
    void moveJoints_sameRequestIdTwice_executesOnceAndRepeatsOutcome() {
        SimulatedController c = controller(0);
        MotionResult first = c.moveJoints(42, new double[] {0.5, 0, 0, 0, 0, 0});
        c.moveJoints(43, new double[] {0, 0, 0, 0, 0, 0});
        MotionResult again = c.moveJoints(42, new double[] {0.5, 0, 0, 0, 0, 0});
        assertEquals(first, again);
        assertEquals(1, c.executions(42));
        assertEquals(2, c.motionsExecuted());
        assertArrayEquals(new double[6], c.readJoints(), 0, "the repeated id must not move the robot back");
    }

    @Test
    void moveLinear_reachableTarget_toolEndsAtTargetInWorkObject() {
        SimulatedController c = controller(0);
        Pose tool = Pose.translation(0, 0, 0.1);
        Pose wobj = Pose.translation(0.5, 0, 0.2).times(Pose.rotZ(0.3));
        c.setTool(tool);
        c.setWorkObject(wobj);
        Pose target = Pose.translation(0.4, -0.1, 0.9).times(Pose.rotY(0.4)).times(Pose.rotZ(-0.3));
        c.moveLinear(0, target);
        Pose reached = c.readPose();
        assertEquals(0, reached.distanceTo(target), 1e-9);
        assertEquals(0, reached.angleTo(target), 1e-9);
    }

    @Test
    void moveLinear_pathOutsideLimits_refusedWithoutMoving() {
        SimulatedController c = controller(0);
        Pose start = c.readPose();
        // x = 0.8 + 0.3 q1 with |q1| <= 2: x = 1.5 m is outside.
        Pose target = Pose.translation(1.5, 0, 1.0).times(Pose.rotZ(0));
        CommsException.Refused e = assertThrows(CommsException.Refused.class, () -> c.moveLinear(0, target));
        assertEquals(ErrorCode.JOINT_LIMIT, e.code());
        assertEquals(0, c.readPose().distanceTo(start), 0);
    }

    @Test
    void measure_withoutNoise_isTrueTargetInTrackerFrameWhateverTheTool() {
        SimulatedController c = controller(0);
        c.setTool(Pose.translation(0.01, 0.02, 0.15));
        c.moveJoints(0, new double[] {0.3, -0.2, 0.1, 0.4, -0.3, 0.2});
        Vec3 m = c.measure();
        GantryRobot g = new GantryRobot();
        assertEquals(0, m.minus(g.truePoint(c.readJoints())).norm(), 1e-12);
        Vec3 nominal = GantryRobot.TRACKER_T_BASE.times(c.robot().nominalFlange(c.readJoints())).apply(GantryRobot.TARGET);
        assertEquals(0.0005, m.minus(nominal).norm(), 1e-9, "the tracker sees the true robot, not the nominal model");
    }

    @Test
    void measureReading_afterMoves_reportsApproachDirectionsClockAndNoTemperature() {
        SimulatedController c = controller(0);
        c.moveJoints(0, new double[] {0.3, -0.2, 0, 0, 0, 0});
        c.moveJoints(0, new double[] {0.2, -0.2, 0.1, 0, 0, 0});
        var r = c.measureReading();
        assertArrayEquals(new int[] {-1, -1, 1, 0, 0, 0}, r.conditions().directions());
        assertEquals(c.clockS(), r.conditions().timeS(), 0);
        assertTrue(r.conditions().timeS() > 0);
        assertTrue(Double.isNaN(r.conditions().tempC()), "the gantry does not model temperature");
        assertEquals(0, r.conditions().payloadKg(), 0);
    }

    @Test
    void measure_withNoise_scatterMatchesSigma() {
        double sigma = 0.05e-3;
        SimulatedController c = controller(sigma);
        int n = 4000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; i++) {
            double x = c.measure().x();
            sum += x;
            sum2 += x * x;
        }
        double sd = Math.sqrt(sum2 / n - (sum / n) * (sum / n));
        assertEquals(sigma, sd, 0.1 * sigma);
    }

    @Test
    void storeProgram_checksumMismatch_storesNothing() {
        SimulatedController c = controller(0);
        byte[] text = Programs.square().getBytes(StandardCharsets.UTF_8);
        CommsException.Refused e = assertThrows(CommsException.Refused.class,
                () -> c.storeProgram("square", text, text.length, Checksums.crc32(text) ^ 1));
        assertEquals(ErrorCode.CHECKSUM_MISMATCH, e.code());
        assertTrue(c.listPrograms().isEmpty());
    }

    @Test
    void storeProgram_syntaxError_storesNothing() {
        SimulatedController c = controller(0);
        byte[] text = "MODULE m\nPROC main()\n  MoveL [[1,2],[1,0,0,0]], v100, fine, tool0;\nENDPROC\nENDMODULE\n".getBytes(StandardCharsets.UTF_8);
        CommsException.Refused e = assertThrows(CommsException.Refused.class, () -> c.downloadProgram("bad", text));
        assertEquals(ErrorCode.PROGRAM_SYNTAX, e.code());
        assertTrue(e.getMessage().contains("bad:3:9"), "names line and column: " + e.getMessage());
        assertTrue(c.listPrograms().isEmpty());
    }

    @Test
    void startProgram_squareProgram_runsAllMovesAndEndsAtLastTarget() throws Exception {
        SimulatedController c = controller(0);
        c.downloadProgram("square", Programs.square().getBytes(StandardCharsets.UTF_8));
        c.startProgram(0, "square");
        c.awaitIdle(Duration.ofSeconds(10));
        ControllerStatus st = c.readStatus();
        assertEquals(ControllerStatus.State.IDLE, st.state(), String.valueOf(st));
        assertEquals(Programs.SQUARE_MOVES, c.motionsExecuted());
        Pose end = c.readPose();
        assertEquals(0, end.distanceTo(Pose.translation(0.9, 0.1, 1.0)), 1e-9);
        assertTrue(st.clockS() > 0);
    }

    @Test
    void startProgram_unreachableTarget_stopsWithErrorStatus() throws Exception {
        SimulatedController c = controller(0);
        String prog = "MODULE m\nPROC main()\n  MoveAbsJ [[10,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;\n"
                + "  MoveL [[5000,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;\nENDPROC\nENDMODULE\n";
        c.downloadProgram("far", prog.getBytes(StandardCharsets.UTF_8));
        c.startProgram(0, "far");
        c.awaitIdle(Duration.ofSeconds(10));
        ControllerStatus st = c.readStatus();
        assertEquals(ControllerStatus.State.ERROR, st.state());
        assertEquals(1, c.motionsExecuted());
        assertNotNull(st.lastError());
    }

    @Test
    void startProgram_moveC_followsArcThroughCirPointInArcLengthOverSpeed() throws Exception {
        SimulatedController c = controller(0);
        String prog = "MODULE arc\nPROC main()\n"
                + "  MoveL [[800,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n"
                + "  MoveC [[900,100,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], "
                + "[[1000,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;\n"
                + "ENDPROC\nENDMODULE\n";
        c.downloadProgram("arc", prog.getBytes(StandardCharsets.UTF_8));
        c.startProgram(0, "arc");
        c.awaitIdle(Duration.ofSeconds(10));
        ControllerStatus st = c.readStatus();
        assertEquals(ControllerStatus.State.IDLE, st.state(), String.valueOf(st));
        assertEquals(0, c.readPose().distanceTo(Pose.translation(1.0, 0, 1.0)), 1e-9);
        // The first move starts at the zero pose, which is (0.8, 0, 1.0): no motion time; the arc
        // is a half circle of radius 0.1 m at 0.1 m/s (a straight line would take 2 s).
        assertEquals(Math.PI, st.clockS(), 0.01 * Math.PI);
        // Through the CirPoint, not its mirror image: joint 2 (y) rose to 1/3 (y = 0.1 m) and came back,
        // so its last approach was downwards.
        assertEquals(-1, c.lastDirection()[1]);
    }

    @Test
    void startProgram_moveCCollinearPoints_errorStatusNamesTheInstruction() throws Exception {
        SimulatedController c = controller(0);
        String prog = "MODULE arc\nPROC main()\n"
                + "  MoveC [[900,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], "
                + "[[1000,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;\n"
                + "ENDPROC\nENDMODULE\n";
        c.downloadProgram("arc", prog.getBytes(StandardCharsets.UTF_8));
        c.startProgram(0, "arc");
        c.awaitIdle(Duration.ofSeconds(10));
        ControllerStatus st = c.readStatus();
        assertEquals(ControllerStatus.State.ERROR, st.state());
        assertEquals(ErrorCode.PATH_UNREACHABLE, st.lastError());
        assertTrue(st.lastErrorMessage().contains("MoveC") && st.lastErrorMessage().contains("line 3"), st.lastErrorMessage());
        assertEquals(0, c.motionsExecuted());
    }

    @Test
    void startProgram_cannotBeSimulated_refusedWithLineAndNothingMoves() {
        SimulatedController c = controller(0);
        String prog = "MODULE m\nPROC main()\n  MoveAbsJ [[10,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;\n"
                + "  missing;\nENDPROC\nENDMODULE\n";
        c.downloadProgram("m", prog.getBytes(StandardCharsets.UTF_8));
        CommsException.Refused e = assertThrows(CommsException.Refused.class, () -> c.startProgram(0, "m"));
        assertEquals(ErrorCode.PROGRAM_NOT_SIMULATED, e.code());
        assertTrue(e.getMessage().contains("m:4") && e.getMessage().contains("missing"), e.getMessage());
        assertEquals(0, c.motionsExecuted());
        assertEquals(ControllerStatus.State.IDLE, c.readStatus().state());
    }

    @Test
    void startProgram_controlFlowLoop_runsEveryIterationsMove() throws Exception {
        SimulatedController c = controller(0);
        String prog = "MODULE loop\n  CONST robtarget p1 := [[800,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n"
                + "  PROC main()\n    FOR i FROM 1 TO 3 DO\n      MoveL Offs(p1, 50 * i, 0, 0), v200, fine, tool0;\n    ENDFOR\n"
                + "    TPWrite \"done\";\n  ENDPROC\nENDMODULE\n";
        c.downloadProgram("loop", prog.getBytes(StandardCharsets.UTF_8));
        c.startProgram(0, "loop");
        c.awaitIdle(Duration.ofSeconds(10));
        assertEquals(ControllerStatus.State.IDLE, c.readStatus().state(), String.valueOf(c.readStatus()));
        assertEquals(3, c.motionsExecuted());
        assertEquals(0, c.readPose().distanceTo(Pose.translation(0.95, 0, 1.0)), 1e-9);
    }

    @Test
    void startProgram_weldingWithIo_runsEveryMotion() throws Exception {
        SimulatedController c = controller(0);
        String prog = "MODULE weld\n  CONST robtarget p1 := [[800,0,1000],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n"
                + "  PERS seamdata sm1:=[0.5,0.5];\n  PERS welddata wd1:=[6,0];\n  VAR triggdata gas;\n"
                + "  PROC main()\n    SetDO doClamp, 1;\n    WaitDI diClamped, 1;\n    TriggIO gas, 0.1\\Time\\DOp:=doGas, 1;\n"
                + "    TriggL Offs(p1, 0, 0, 20), v200, gas, fine, tool0;\n"
                + "    ArcLStart p1, v100, sm1, wd1, fine, tool0;\n    ArcLEnd Offs(p1, 50, 0, 0), v100, sm1, wd1, fine, tool0;\n"
                + "    PulseDO doDone;\n  ENDPROC\nENDMODULE\n";
        c.downloadProgram("weld", prog.getBytes(StandardCharsets.UTF_8));
        c.startProgram(0, "weld");
        c.awaitIdle(Duration.ofSeconds(10));
        assertEquals(ControllerStatus.State.IDLE, c.readStatus().state(), String.valueOf(c.readStatus()));
        assertEquals(3, c.motionsExecuted());
        assertEquals(0, c.readPose().distanceTo(Pose.translation(0.85, 0, 1.0)), 1e-9);
    }
}
