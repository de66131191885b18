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
        return new SimulatedController(new GantryRobot(), SimulatedController.Settings.defaults(7).withNoise(noiseM));
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
    void measure_withoutNoise_isTrackerTimesTrueRobotTimesToolOrigin() {
        SimulatedController c = controller(0);
        c.setTool(Pose.translation(0.01, 0.02, 0.15));
        c.moveJoints(0, new double[] {0.3, -0.2, 0.1, 0.4, -0.3, 0.2});
        Vec3 m = c.measure();
        Vec3 expected = c.settings().trackerTbase().times(new GantryRobot().trueFlange(c.readJoints(), new int[6]))
                .apply(new Vec3(0.01, 0.02, 0.15));
        assertEquals(0, m.minus(expected).norm(), 1e-12);
        Vec3 nominal = c.settings().trackerTbase().times(c.robot().nominalFlange(c.readJoints())).apply(new Vec3(0.01, 0.02, 0.15));
        assertEquals(0.0005, m.minus(nominal).norm(), 1e-9, "the tracker sees the true robot, not the nominal model");
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
        assertTrue(e.getMessage().contains("line 3"), e.getMessage());
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
}
