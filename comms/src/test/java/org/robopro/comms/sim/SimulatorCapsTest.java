package org.robopro.comms.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.comms.CommsException;
import org.robopro.comms.ErrorCode;

/** The simulator bounds what a client can make it hold: connections and stored programs. */
class SimulatorCapsTest {
    static String firstLine(Socket s) throws Exception {
        s.setSoTimeout(3000);
        return new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.ISO_8859_1)).readLine();
    }

    @Test
    void connectionsBeyondTheLimit_areRefusedWithAReply_andThreadsStayBounded() throws Exception {
        SimulatedController sim = TestSupport.gantryController(0);
        try (TcpControllerServer server = new TcpControllerServer(new ProtocolHandler(sim), InetAddress.getLoopbackAddress(), 0, null)) {
            int threadsBefore = Thread.activeCount();
            List<Socket> idle = new ArrayList<>();
            try {
                for (int i = 0; i < TcpControllerServer.MAX_CONNECTIONS; i++) idle.add(new Socket("127.0.0.1", server.port()));
                // Each open connection is served: a ping on the last one is answered.
                Socket last = idle.get(idle.size() - 1);
                last.getOutputStream().write("00 #".getBytes(StandardCharsets.ISO_8859_1));
                assertEquals("0 1 ", firstLine(last));
                for (int extra = 0; extra < 50; extra++) {
                    try (Socket over = new Socket("127.0.0.1", server.port())) {
                        String reply = firstLine(over);
                        assertTrue(reply != null && reply.contains(ErrorCode.TOO_MANY_CONNECTIONS.wire()) && reply.contains("at most"), reply);
                    }
                }
                assertTrue(Thread.activeCount() - threadsBefore <= TcpControllerServer.MAX_CONNECTIONS + 4,
                        "threads " + Thread.activeCount() + " (before " + threadsBefore + ")");
                idle.remove(0).close();
                long deadline = System.currentTimeMillis() + 3000;
                String reply = null;
                while (System.currentTimeMillis() < deadline) {
                    try (Socket again = new Socket("127.0.0.1", server.port())) {
                        again.getOutputStream().write("00 #".getBytes(StandardCharsets.ISO_8859_1));
                        reply = firstLine(again);
                        if ("0 1 ".equals(reply)) break;
                    }
                    Thread.sleep(20);
                }
                assertEquals("0 1 ", reply, "a freed slot serves again");
            } finally {
                for (Socket s : idle) s.close();
            }
        }
    }

    @Test
    void programsBeyondTheLimit_areRefused_replacingOneStillWorks() {
        SimulatedController sim = TestSupport.gantryController(0);
        for (int i = 0; i < SimulatedController.MAX_PROGRAMS; i++) sim.downloadProgram("p" + i, program("p" + i));
        CommsException.Refused e = assertThrows(CommsException.Refused.class, () -> sim.downloadProgram("extra", program("extra")));
        assertEquals(ErrorCode.STORAGE_FULL, e.code());
        assertTrue(e.getMessage().contains("limit") && e.getMessage().contains("nothing stored"), e.getMessage());
        sim.downloadProgram("p0", program("p0"));
        assertEquals(SimulatedController.MAX_PROGRAMS, sim.listPrograms().size());
    }

    static byte[] program(String name) {
        return ("MODULE " + name + "\n  PROC main()\n    WaitTime 0.1;\n  ENDPROC\nENDMODULE\n").getBytes(StandardCharsets.UTF_8);
    }
}
