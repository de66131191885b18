package org.robopro.comms.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.link.FramedLink;
import org.robopro.comms.link.SerialPortByteLink;
import org.robopro.comms.link.SocatPair;
import org.robopro.comms.sim.ProtocolHandler;
import org.robopro.comms.sim.SerialControllerServer;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.comms.sim.TcpControllerServer;
import org.robopro.comms.sim.TestSupport;

/**
 * Fault-injection soaks of both transports that check every value received against what was
 * sent: 0 lost, 0 duplicated, 0 corrupted. Sized for CI; {@code -Dsoak.commands=N} runs longer
 * (docs/controller-link.md has the full-size figures).
 */
class LinkSoakTest {
    static final int COMMANDS = Integer.getInteger("soak.commands", 10_002);
    @TempDir Path dir;

    static CommandInvoker invoker(org.robopro.comms.ControllerReceiver client, Duration timeout) {
        return new CommandInvoker(client, CommandInvoker.Options.DEFAULT
                .withReplyTimeout(timeout).withMaxRetries(20).withRetryDelay(Duration.ZERO));
    }

    @Test
    void tcp_faultsBothWaysIncludingDisconnects_everyValueArrivesIntact() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        FaultInjector replies = FaultInjector.uniformWithDisconnect(31, 0.025, 20);
        FaultInjector requests = FaultInjector.uniformWithDisconnect(32, 0.025, 20);
        try (TcpControllerServer server = new TcpControllerServer(new ProtocolHandler(sim), InetAddress.getLoopbackAddress(), 0,
                replies, requests);
             ProtocolClient client = new ProtocolClient(new TcpRequestChannel("127.0.0.1", server.port()));
             CommandInvoker inv = invoker(client, Duration.ofMillis(60))) {
            LinkSoak.Figures f = LinkSoak.run(inv, sim, COMMANDS, 7);
            System.out.println("TCP soak: " + f + "; replies " + replies + "; requests " + requests + "; " + client.channel().describe());
            assertTrue(((TcpRequestChannel) client.channel()).checksummed(), "the link runs in checksum mode");
            assertFigures(f, replies, requests);
        }
    }

    @Test
    void tcp_withoutChecksums_theSameFaultsCorruptValues() throws Exception {
        // The defect the checksum mode fixes: plain open_abb text carries no checksum, so a damaged
        // digit is taken as a value (or a damaged request moves the robot elsewhere).
        SimulatedController sim = TestSupport.gantryController(0);
        FaultInjector replies = FaultInjector.uniformWithDisconnect(31, 0.025, 20);
        FaultInjector requests = FaultInjector.uniformWithDisconnect(32, 0.025, 20);
        try (TcpControllerServer server = new TcpControllerServer(new ProtocolHandler(sim), InetAddress.getLoopbackAddress(), 0,
                replies, requests);
             ProtocolClient client = new ProtocolClient(new TcpRequestChannel("127.0.0.1", server.port(), Duration.ofSeconds(3),
                     Duration.ofMillis(30), false));
             CommandInvoker inv = invoker(client, Duration.ofMillis(60))) {
            LinkSoak.Figures f = LinkSoak.run(inv, sim, 3000, 7);
            System.out.println("TCP soak without checksums: " + f);
            assertTrue(f.corrupted() > 0, f.toString());
        }
    }

    @Test
    void serial_faultsBothWays_everyValueArrivesIntact() throws Exception {
        try (SocatPair pty = new SocatPair(dir)) {
            SimulatedController sim = TestSupport.gantryController(0);
            FramedLink.Options opts = new FramedLink.Options(Duration.ofMillis(30), 10);
            FaultInjector simFaults = FaultInjector.uniform(41, 0.025, 20), clientFaults = FaultInjector.uniform(42, 0.025, 20);
            try (SerialControllerServer server = new SerialControllerServer(new ProtocolHandler(sim),
                    () -> new SerialPortByteLink(pty.b(), 115200), opts, simFaults);
                 ProtocolClient client = new ProtocolClient(new SerialRequestChannel(() -> new SerialPortByteLink(pty.a(), 115200),
                         "serial " + pty.a(), opts, clientFaults));
                 CommandInvoker inv = invoker(client, Duration.ofSeconds(2))) {
                LinkSoak.Figures f = LinkSoak.run(inv, sim, COMMANDS, 8);
                System.out.println("serial soak: " + f + "; simulator side " + simFaults + "; client side " + clientFaults);
                assertFigures(f, simFaults, clientFaults);
            }
        }
    }

    static void assertFigures(LinkSoak.Figures f, FaultInjector a, FaultInjector b) {
        assertTrue(f.commands() >= 10_000 || f.commands() == COMMANDS);
        assertEquals(0, f.failed(), "every command must succeed: " + f);
        assertEquals(0, f.lost(), f.toString());
        assertEquals(0, f.duplicated(), f.toString());
        assertEquals(0, f.corrupted(), f.toString());
        // >= 2 % faults each way, every kind present.
        long ta = a.faults() + a.count(FaultInjector.Fault.NONE), tb = b.faults() + b.count(FaultInjector.Fault.NONE);
        assertTrue(a.faults() >= 0.02 * ta && b.faults() >= 0.02 * tb, a + " / " + b);
        for (FaultInjector.Fault k : new FaultInjector.Fault[] {FaultInjector.Fault.DROP, FaultInjector.Fault.CORRUPT,
                FaultInjector.Fault.DUPLICATE, FaultInjector.Fault.DELAY})
            assertTrue(a.count(k) > 0 && b.count(k) > 0, k + ": " + a + " / " + b);
    }
}
