package org.robopro.comms.client;

import static org.junit.jupiter.api.Assertions.*;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.Commands;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.MotionResult;
import org.robopro.comms.ProgramInfo;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.protocol.Checksums;
import org.robopro.comms.sim.ProtocolHandler;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.comms.sim.TcpControllerServer;
import org.robopro.comms.sim.TestSupport;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

class ProtocolClientTcpTest {
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : toClose) c.close();
    }

    private <T extends AutoCloseable> T track(T c) {
        toClose.add(0, c);
        return c;
    }

    private TcpControllerServer server(SimulatedController c, FaultInjector faults) throws Exception {
        return track(new TcpControllerServer(new ProtocolHandler(c), InetAddress.getLoopbackAddress(), 0, faults));
    }

    private CommandInvoker invoker(int port, CommandInvoker.Options opts) {
        ProtocolClient client = track(new ProtocolClient(new TcpRequestChannel("127.0.0.1", port)));
        return track(new CommandInvoker(client, opts));
    }

    @Test
    void fullSession_everyCommandKind_resultsMatchSimulator() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        TcpControllerServer server = server(sim, null);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT);
        inv.execute(Commands.ping());
        Pose tool = Pose.translation(0.01, 0, 0.12);
        inv.execute(Commands.setTool(tool));
        inv.execute(Commands.setWorkObject(Pose.translation(0.1, 0, 0)));
        inv.execute(Commands.setSpeed(new org.robopro.programs.SpeedData(0.25, 1, 0, 0)));
        // z5 as open_abb sends it (tcp 5 mm, ori 8 mm, 0.8 deg): the simulator holds RAPID's zonedata.
        inv.execute(Commands.setZone(org.robopro.programs.ZoneData.predefined("z5").orElseThrow()));
        org.robopro.programs.ZoneData z5 = sim.zone();
        assertEquals(0.005, z5.pzoneTcp(), 1e-12);
        assertEquals(0.008, z5.pzoneOri(), 1e-12);
        assertEquals(Math.toRadians(0.8), z5.zoneOri(), 1e-9);
        assertTrue(!z5.finep());
        inv.execute(Commands.setZone(org.robopro.programs.ZoneData.FINE));
        assertTrue(sim.zone().finep());
        double[] target = {0.1, -0.2, 0.3, 0.2, -0.1, 0.05};
        MotionResult m = inv.execute(Commands.moveJoints(target));
        assertTrue(m.motionTimeS() > 0);
        assertArrayEquals(target, inv.execute(Commands.readJoints()), 1e-6);
        assertEquals(tool, sim.tool());
        Pose p = inv.execute(Commands.readPose());
        assertEquals(0, p.distanceTo(sim.readPose()), 2e-6);
        Pose goal = Pose.translation(0.75, 0.05, 1.1).times(Pose.rotY(0.2));
        inv.execute(Commands.moveLinear(goal));
        assertEquals(0, inv.execute(Commands.readPose()).distanceTo(goal), 2e-6);
        Vec3 meas = inv.execute(Commands.measure());
        assertEquals(0, meas.minus(TestSupport.gantryTruePoint(sim)).norm(), 1e-6);
        var reading = inv.execute(Commands.measureReading());
        assertEquals(0, reading.position().minus(meas).norm(), 1e-6);
        assertArrayEquals(sim.lastDirection(), reading.conditions().directions());
        assertEquals(sim.clockS(), reading.conditions().timeS(), 1e-3);

        byte[] prog = TestSupport.squareProgram();
        ProgramInfo info = inv.execute(Commands.downloadProgram("square", prog));
        assertEquals(Checksums.crc32(prog), info.crc32());
        assertArrayEquals(prog, inv.execute(Commands.uploadProgram("square")));
        assertEquals(List.of(info), inv.execute(Commands.listPrograms()));
        long before = sim.motionsExecuted();
        inv.execute(Commands.startProgram("square"));
        sim.awaitIdle(Duration.ofSeconds(10));
        ControllerStatus st = inv.execute(Commands.readStatus());
        assertEquals(ControllerStatus.State.IDLE, st.state());
        assertEquals("square", st.program());
        assertTrue(sim.motionsExecuted() > before);
        assertEquals(1, inv.history().stream().filter(r -> r.description().startsWith("download")).count());
    }

    @Test
    void largeProgram_manyChunks_transferVerifiedBothWays() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        TcpControllerServer server = server(sim, null);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT);
        byte[] prog = TestSupport.longProgram(400); // ~30 kB, many chunks
        assertTrue(prog.length > 20_000);
        inv.execute(Commands.downloadProgram("long", prog));
        assertArrayEquals(prog, sim.uploadProgram("long"));
        assertArrayEquals(prog, inv.execute(Commands.uploadProgram("long")));
    }

    @Test
    void refusedMotion_failsWithCodeAndIsNotRetried() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        TcpControllerServer server = server(sim, null);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT);
        CompletableFuture<MotionResult> f = inv.submit(Commands.moveJoints(new double[] {0, 0, 0, 0, 1.5, 0}));
        CompletionException e = assertThrows(CompletionException.class, f::join);
        assertEquals(ErrorCode.JOINT_LIMIT, ((CommsException.Refused) e.getCause()).code());
        assertEquals(0, sim.motionsExecuted());
        assertEquals(1, inv.history().get(inv.history().size() - 1).attempt());
    }

    @Test
    void silentController_timeoutGivesClearError() throws Exception {
        try (ServerSocket mute = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Thread t = new Thread(() -> {
                try (Socket s = mute.accept()) {
                    s.getInputStream().readAllBytes();
                } catch (Exception ignored) {
                    // test ends
                }
            });
            t.setDaemon(true);
            t.start();
            CommandInvoker inv = invoker(mute.getLocalPort(), CommandInvoker.Options.DEFAULT
                    .withReplyTimeout(Duration.ofMillis(300)).withMaxRetries(1).withRetryDelay(Duration.ZERO));
            CompletionException e = assertThrows(CompletionException.class, () -> inv.submit(Commands.ping()).join());
            assertInstanceOf(CommsException.Timeout.class, e.getCause());
            assertTrue(e.getCause().getMessage().contains("did not answer"), e.getCause().getMessage());
            assertTrue(e.getCause().getMessage().contains(":" + mute.getLocalPort()), e.getCause().getMessage());
        }
    }

    @Test
    void noController_connectionRefusedGivesClearError() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        CommandInvoker inv = invoker(port, CommandInvoker.Options.DEFAULT.withMaxRetries(1).withRetryDelay(Duration.ZERO));
        CompletionException e = assertThrows(CompletionException.class, () -> inv.submit(Commands.readJoints()).join());
        assertInstanceOf(CommsException.LinkDown.class, e.getCause());
        assertTrue(e.getCause().getMessage().contains("cannot connect"), e.getCause().getMessage());
    }

    @Test
    void droppedLink_nextCommandReconnectsAndSucceeds() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        TcpControllerServer server = server(sim, null);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT.withRetryDelay(Duration.ofMillis(20)));
        inv.execute(Commands.ping());
        server.dropClients();
        Thread.sleep(50);
        inv.execute(Commands.moveJoints(new double[] {0.2, 0, 0, 0, 0, 0}));
        assertEquals(1, sim.motionsExecuted());
        assertArrayEquals(new double[] {0.2, 0, 0, 0, 0, 0}, inv.execute(Commands.readJoints()), 1e-6);
    }

    @Test
    void disconnectDuringDownload_retryStoresVerifiedProgramOnce() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        TcpControllerServer server = server(sim, null);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT.withRetryDelay(Duration.ofMillis(20)));
        byte[] prog = TestSupport.longProgram(100);
        server.cutConnectionAtDownloadChunk(3);
        inv.execute(Commands.downloadProgram("cut", prog));
        assertArrayEquals(prog, sim.uploadProgram("cut"));
        var last = inv.history().get(inv.history().size() - 1);
        assertEquals(2, last.attempt(), "the download was re-sent once after the cut");
    }

    @Test
    void disconnectDuringDownload_withoutRetry_nothingHalfStored() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        TcpControllerServer server = server(sim, null);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT.withMaxRetries(0));
        server.cutConnectionAtDownloadChunk(2);
        CompletionException e = assertThrows(CompletionException.class,
                () -> inv.submit(Commands.downloadProgram("cut", TestSupport.longProgram(100))).join());
        assertInstanceOf(CommsException.LinkDown.class, e.getCause());
        assertTrue(sim.listPrograms().isEmpty(), "a cut transfer must leave nothing stored");
        Thread.sleep(50);
        assertTrue(inv.execute(Commands.listPrograms()).isEmpty());
    }

    @Test
    void faultyReplies_manyMotions_eachExecutedExactlyOnceNoneLost() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        FaultInjector faults = FaultInjector.uniform(11, 0.08, 40);
        TcpControllerServer server = server(sim, faults);
        CommandInvoker inv = invoker(server.port(), CommandInvoker.Options.DEFAULT
                .withReplyTimeout(Duration.ofMillis(250)).withMaxRetries(8).withRetryDelay(Duration.ZERO));
        Random rnd = new Random(5);
        List<Commands.MoveJoints> moves = new ArrayList<>();
        List<CompletableFuture<MotionResult>> futures = new ArrayList<>();
        for (int i = 0; i < 250; i++) {
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) q[j] = (rnd.nextDouble() - 0.5);
            Commands.MoveJoints m = Commands.moveJoints(q);
            moves.add(m);
            futures.add(inv.submit(m));
        }
        for (CompletableFuture<MotionResult> f : futures) f.join(); // none lost: every one succeeded
        int duplicated = 0, lost = 0;
        for (Commands.MoveJoints m : moves) {
            int n = sim.executions(m.requestId());
            if (n == 0) lost++;
            if (n > 1) duplicated++;
        }
        System.out.println("TCP with " + faults + ": lost " + lost + ", duplicated " + duplicated);
        assertEquals(0, lost);
        assertEquals(0, duplicated);
        assertEquals(moves.size(), sim.motionsExecuted());
        assertTrue(faults.faults() > 5, "the faults must actually happen: " + faults);
    }

    /** A stand-in for RAPID/SERVER.mod: replies without terminator, ok 0 for unknown instructions. */
    @Test
    void plainServerMod_clientFallsBackAndNeverResendsMotion() throws Exception {
        List<String> received = java.util.Collections.synchronizedList(new ArrayList<>());
        try (ServerSocket ss = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Thread t = new Thread(() -> {
                try (Socket s = ss.accept()) {
                    InputStream in = s.getInputStream();
                    OutputStream out = s.getOutputStream();
                    StringBuilder sb = new StringBuilder();
                    int ch;
                    while ((ch = in.read()) >= 0) {
                        sb.append((char) ch);
                        if (ch != '#') continue;
                        String msg = sb.toString().strip();
                        sb.setLength(0);
                        received.add(msg);
                        int code = Integer.parseInt(msg.split(" ")[0]);
                        String reply = switch (code) {
                            case 4 -> "4 1 10.00 -5.50 20.25 0.00 30.00 -0.75";
                            case 3 -> "3 1 1000.00 0.00 1615.00 0.707 0.000 0.707 0.000";
                            case 2 -> null; // a move whose reply gets lost
                            case 0, 6, 7, 8, 9 -> code + " 1 ";
                            default -> code + " 0 ";
                        };
                        if (reply != null) {
                            out.write(reply.getBytes(StandardCharsets.US_ASCII));
                            out.flush();
                        }
                    }
                } catch (Exception ignored) {
                    // test ends
                }
            });
            t.setDaemon(true);
            t.start();
            ProtocolClient client = track(new ProtocolClient(new TcpRequestChannel("127.0.0.1", ss.getLocalPort())));
            CommandInvoker inv = track(new CommandInvoker(client, CommandInvoker.Options.DEFAULT
                    .withReplyTimeout(Duration.ofMillis(400)).withRetryDelay(Duration.ZERO)));
            double[] q = inv.execute(Commands.readJoints());
            assertEquals(-0.75, Math.toDegrees(q[5]), 1e-9);
            assertFalse(client.extended());
            Pose p = inv.execute(Commands.readPose());
            assertEquals(1.615, p.z(), 1e-9);
            inv.execute(Commands.setTool(Pose.IDENTITY));
            CompletionException e = assertThrows(CompletionException.class,
                    () -> inv.submit(Commands.moveJoints(new double[] {0, 0, 0, 0, 0.5, 0})).join());
            assertTrue(e.getCause().getMessage().contains("not re-sent"), e.getCause().getMessage());
            assertEquals(1, received.stream().filter(m -> m.startsWith("02 ")).count(), "a motion must never be sent twice");
            CommsException.Refused r = assertThrows(CommsException.Refused.class, () -> inv.execute(Commands.listPrograms()));
            assertTrue(r.getMessage().contains("plain open_abb"), r.getMessage());
        }
    }
}
