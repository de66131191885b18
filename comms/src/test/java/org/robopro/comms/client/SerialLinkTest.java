package org.robopro.comms.client;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.Commands;
import org.robopro.comms.ControllerCommand;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.link.FramedLink;
import org.robopro.comms.link.SerialPortByteLink;
import org.robopro.comms.link.SocatPair;
import org.robopro.comms.sim.ProtocolHandler;
import org.robopro.comms.sim.SerialControllerServer;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.comms.sim.TestSupport;

/** The serial path end to end: jSerialComm on a real pty pair from socat, simulator on the other end. */
class SerialLinkTest {
    private static final FramedLink.Options PTY = new FramedLink.Options(Duration.ofMillis(30), 10);

    @TempDir Path dir;

    private static SerialRequestChannel client(String device, FaultInjector faults) {
        return new SerialRequestChannel(() -> new SerialPortByteLink(device, 115200), "serial " + device, PTY, faults);
    }

    @Test
    void commandsAndProgramTransfer_overPty_matchSimulator() throws Exception {
        try (SocatPair pty = new SocatPair(dir)) {
            SimulatedController sim = TestSupport.gantryController(0);
            try (SerialControllerServer server = new SerialControllerServer(new ProtocolHandler(sim),
                    () -> new SerialPortByteLink(pty.b(), 115200), PTY, null);
                 ProtocolClient client = new ProtocolClient(client(pty.a(), null));
                 CommandInvoker inv = new CommandInvoker(client)) {
                inv.execute(Commands.ping());
                assertTrue(client.extended());
                double[] q = {0.1, 0.2, -0.3, 0.4, 0.5, -0.6};
                inv.execute(Commands.moveJoints(q));
                assertArrayEquals(q, inv.execute(Commands.readJoints()), 1e-6);
                byte[] prog = TestSupport.longProgram(60);
                inv.execute(Commands.downloadProgram("serialprog", prog));
                assertArrayEquals(prog, sim.uploadProgram("serialprog"));
                assertArrayEquals(prog, inv.execute(Commands.uploadProgram("serialprog")));
            }
        }
    }

    @Test
    void soak_tenThousandCommandsWithTwoPercentFaults_noneLostNoneDuplicated() throws Exception {
        try (SocatPair pty = new SocatPair(dir)) {
            SimulatedController sim = TestSupport.gantryController(0);
            FaultInjector simFaults = FaultInjector.uniform(101, 0.02, 20);
            FaultInjector clientFaults = FaultInjector.uniform(202, 0.02, 20);
            try (SerialControllerServer server = new SerialControllerServer(new ProtocolHandler(sim),
                    () -> new SerialPortByteLink(pty.b(), 115200), PTY, simFaults);
                 ProtocolClient client = new ProtocolClient(client(pty.a(), clientFaults));
                 CommandInvoker inv = new CommandInvoker(client, CommandInvoker.Options.DEFAULT
                         .withReplyTimeout(Duration.ofSeconds(2)).withMaxRetries(5).withRetryDelay(Duration.ZERO))) {
                Random rnd = new Random(9);
                int n = 10_000;
                List<Commands.MoveJoints> moves = new ArrayList<>();
                List<CompletableFuture<?>> futures = new ArrayList<>(n);
                long t0 = System.nanoTime();
                for (int i = 0; i < n; i++) {
                    ControllerCommand<?> c;
                    if (i % 3 == 0) {
                        double[] q = new double[6];
                        for (int j = 0; j < 6; j++) q[j] = rnd.nextDouble() - 0.5;
                        Commands.MoveJoints m = Commands.moveJoints(q);
                        moves.add(m);
                        c = m;
                    } else {
                        c = i % 3 == 1 ? Commands.readJoints() : Commands.ping();
                    }
                    futures.add(inv.submit(c));
                }
                int failed = 0;
                for (CompletableFuture<?> f : futures) {
                    try {
                        f.join();
                    } catch (RuntimeException e) {
                        failed++;
                    }
                }
                double seconds = (System.nanoTime() - t0) * 1e-9;
                int lost = 0, duplicated = 0;
                for (Commands.MoveJoints m : moves) {
                    int k = sim.executions(m.requestId());
                    if (k == 0) lost++;
                    if (k > 1) duplicated++;
                }
                System.out.printf("serial soak: %d commands (%d motions) in %.1f s; failed %d, lost %d, duplicated %d%n",
                        n, moves.size(), seconds, failed, lost, duplicated);
                System.out.println("  client link: " + client.channel().describe() + " " + ((SerialRequestChannel) client.channel()).link().stats() + "; injected " + clientFaults);
                System.out.println("  simulator link: " + server.link().stats() + "; injected " + simFaults);
                assertEquals(0, failed, "every command must succeed");
                assertEquals(0, lost);
                assertEquals(0, duplicated);
                assertEquals(moves.size(), sim.motionsExecuted());
                assertTrue(simFaults.faults() + clientFaults.faults() > 200, "faults must happen: " + simFaults + " " + clientFaults);
            }
        }
    }

    @Test
    void droppedLine_socatRestarted_clientAndSimulatorReconnect() throws Exception {
        try (SocatPair pty = new SocatPair(dir)) {
            SimulatedController sim = TestSupport.gantryController(0);
            try (SerialControllerServer server = new SerialControllerServer(new ProtocolHandler(sim),
                    () -> new SerialPortByteLink(pty.b(), 115200), PTY, null);
                 ProtocolClient client = new ProtocolClient(client(pty.a(), null));
                 CommandInvoker inv = new CommandInvoker(client, CommandInvoker.Options.DEFAULT
                         .withReplyTimeout(Duration.ofSeconds(1)).withMaxRetries(10).withRetryDelay(Duration.ofMillis(300)))) {
                inv.execute(Commands.moveJoints(new double[] {0.1, 0, 0, 0, 0, 0}));
                pty.kill();
                pty.start();
                Commands.MoveJoints m = Commands.moveJoints(new double[] {0.2, 0, 0, 0, 0, 0});
                inv.execute(m);
                assertEquals(1, sim.executions(m.requestId()));
                assertArrayEquals(new double[] {0.2, 0, 0, 0, 0, 0}, inv.execute(Commands.readJoints()), 1e-6);
            }
        }
    }
}
