package org.robopro.comms.sim;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.Commands;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.client.ProtocolClient;
import org.robopro.comms.client.TcpRequestChannel;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.RobotLibrary;
import org.robopro.models.Vec3;

/** The simulated IRB-2000 controller as a process of its own, driven over TCP. */
class ControllerSimProcessTest {
    @TempDir Path dir;

    @Test
    void separateProcess_irb2000_movesRefusesMeasuresAndRunsPrograms() throws Exception {
        Path portFile = dir.resolve("port");
        Path log = dir.resolve("sim.log");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-cp", classPath(), ControllerSim.class.getName(),
                "--tcp", "127.0.0.1:0", "--port-file", portFile.toString(), "--seed", "3", "--error-mm", "0.5", "--noise-mm", "0")
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!Files.exists(portFile) || Files.readString(portFile).isBlank()) {
                assertTrue(p.isAlive(), () -> "simulator exited: " + read(log));
                assertTrue(System.nanoTime() < deadline, () -> "simulator did not start within 30 s: " + read(log));
                Thread.sleep(50);
            }
            int port = Integer.parseInt(Files.readString(portFile).strip());
            KinematicModel nominal = KinematicModel.build(RobotLibrary.load("irb2000"));
            try (ProtocolClient client = new ProtocolClient(new TcpRequestChannel("127.0.0.1", port));
                 CommandInvoker inv = new CommandInvoker(client, CommandInvoker.Options.DEFAULT.withReplyTimeout(Duration.ofSeconds(10)))) {
                inv.execute(Commands.ping());
                assertEquals("irb2000", client.robotName());
                double[] q = {
                        Math.toRadians(20), Math.toRadians(10), Math.toRadians(-15), Math.toRadians(30), Math.toRadians(40), Math.toRadians(-20)};
                var m = inv.execute(Commands.moveJoints(q));
                // joint 6 moves 20 deg at 450 deg/s, joint 1 20 deg at 150 deg/s: at least 0.133 s
                assertTrue(m.motionTimeS() >= Math.toRadians(20) / Math.toRadians(150) - 1e-9, "motion time " + m.motionTimeS());
                assertArrayEquals(q, inv.execute(Commands.readJoints()), 1e-6);
                Pose pose = inv.execute(Commands.readPose());
                assertEquals(0, pose.distanceTo(nominal.flange(q)), 1e-5, "CRobT reports the nominal model");

                CommsException.Refused e = assertThrows(CommsException.Refused.class,
                        () -> inv.execute(Commands.moveJoints(new double[] {0, Math.toRadians(120), 0, 0, 0, 0})));
                assertEquals(ErrorCode.JOINT_LIMIT, e.code());
                assertTrue(e.getMessage().contains("joint 2"), e.getMessage());
                CommsException.Refused far = assertThrows(CommsException.Refused.class,
                        () -> inv.execute(Commands.moveLinear(Pose.translation(5, 0, 1).times(pose.inverse().times(pose)))));
                assertEquals(ErrorCode.UNREACHABLE, far.code());

                Pose goal = Pose.translation(pose.x() - 0.05, pose.y() + 0.05, pose.z() - 0.05)
                        .times(Pose.of(pose.rotationRowMajor(), 0, 0, 0));
                inv.execute(Commands.moveLinear(goal));
                assertEquals(0, inv.execute(Commands.readPose()).distanceTo(goal), 1e-5);

                // The tracker frame is unknown; distances between measured points are frame-free. The
                // target sits nominally 100 mm along the flange z axis (off by ~2 mm), the geometry is off by ~0.5 mm.
                Vec3 m1 = inv.execute(Commands.measure());
                inv.execute(Commands.moveJoints(q));
                Vec3 m0 = inv.execute(Commands.measure());
                Vec3 t = new Vec3(0, 0, 0.1);
                double nominalDistance = goal.times(pose.inverse()).times(nominal.flange(q)).apply(t).minus(nominal.flange(q).apply(t)).norm();
                double dev = Math.abs(m1.minus(m0).norm() - nominalDistance);
                assertTrue(dev > 1e-7 && dev < 0.01, "tracker sees the true robot, sub-mm away from nominal: " + dev);

                String prog = "MODULE demo\n  PROC main()\n"
                        + "    MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n"
                        + "    MoveAbsJ [[10,5,5,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n"
                        + "  ENDPROC\nENDMODULE\n";
                inv.execute(Commands.downloadProgram("demo", prog.getBytes(StandardCharsets.UTF_8)));
                assertEquals(List.of("demo"), inv.execute(Commands.listPrograms()).stream().map(x -> x.name()).toList());
                inv.execute(Commands.startProgram("demo"));
                ControllerStatus st;
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                do {
                    st = inv.execute(Commands.readStatus());
                } while (st.state() == ControllerStatus.State.RUNNING && System.nanoTime() < until);
                assertEquals(ControllerStatus.State.IDLE, st.state(), String.valueOf(st));
                assertArrayEquals(new double[] {Math.toRadians(10), Math.toRadians(5), Math.toRadians(5), 0, Math.toRadians(30), 0},
                        inv.execute(Commands.readJoints()), 1e-6);
            }
        } finally {
            p.destroy();
            if (!p.waitFor(5, TimeUnit.SECONDS)) p.destroyForcibly();
        }
    }

    @Test
    void truthFile_effectWithoutValue_recordsTheDrawnSizeTheRobotHas() throws Exception {
        Path truth = dir.resolve("truth.json");
        ControllerSim.Config c = ControllerSim.Config.tcp("127.0.0.1:0").withSeed(5).withErrorMm(8).withEffects(List.of("backlash:3"))
                .withTruthFile(truth);
        try (ControllerSim sim = ControllerSim.start(c)) {
            var root = new com.fasterxml.jackson.databind.ObjectMapper().readTree(truth.toFile());
            TrueSimulatedRobot robot = (TrueSimulatedRobot) sim.controller().robot();
            assertEquals(5, root.get("seed").asLong());
            assertEquals(8, root.get("error_mm").asDouble());
            assertEquals(0.02, root.get("noise_mm").asDouble());
            assertEquals(8, root.get("nominal_flange_rms_mm").asDouble(), 1.5, "the error over the workspace is near the one asked for");
            assertEquals(1, root.get("effects").size());
            var e = root.get("effects").get(0);
            assertEquals("backlash j3", e.get("label").asText());
            double playRad = robot.effects().get(0).values()[0];
            assertEquals(playRad, e.get("parameters_si").get("b").asDouble(), 1e-15, e.toString());
            double deg = Math.toDegrees(playRad);
            assertTrue(deg >= 0.02 && deg <= 0.05, "drawn in EffectSpec's range: " + deg);
            // The recorded spec reproduces the robot exactly.
            TrueSimulatedRobot again = TrueSimulatedRobot.create(RobotLibrary.load("irb2000"), 9,
                    TrueSimulatedRobot.Options.defaults().withEffects(List.of(e.get("spec").asText())));
            assertEquals(playRad, again.effects().get(0).values()[0], 1e-12);
        }
    }

    @Test
    void startedByAnotherJvm_stdinClosed_simulatorStops() throws Exception {
        Path portFile = dir.resolve("port");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-cp", classPath(), ControllerSim.class.getName(),
                "--tcp", "127.0.0.1:0", "--port-file", portFile.toString(), "--stop-on-stdin-eof")
                .redirectErrorStream(true).redirectOutput(dir.resolve("sim.log").toFile()).start();
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!Files.exists(portFile) || Files.readString(portFile).isBlank()) {
                assertTrue(p.isAlive() && System.nanoTime() < deadline, () -> "simulator did not start: " + read(dir.resolve("sim.log")));
                Thread.sleep(50);
            }
            assertTrue(p.isAlive());
            p.getOutputStream().close(); // what the OS does when the parent JVM dies
            assertTrue(p.waitFor(10, TimeUnit.SECONDS), "the simulator stops when its parent's pipe closes");
            assertEquals(0, p.exitValue());
        } finally {
            p.destroyForcibly();
        }
    }

    private static String read(Path p) {
        try {
            return Files.exists(p) ? Files.readString(p) : "(no output)";
        } catch (java.io.IOException e) {
            return e.toString();
        }
    }

    /** This JVM's module path and class path as a child's class path (the tests may run on the module path). */
    private static String classPath() {
        String cp = System.getProperty("java.class.path", ""), mp = System.getProperty("jdk.module.path", "");
        return mp.isEmpty() ? cp : cp.isEmpty() ? mp : mp + java.io.File.pathSeparator + cp;
    }
}
