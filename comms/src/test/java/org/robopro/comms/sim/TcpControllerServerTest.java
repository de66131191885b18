package org.robopro.comms.sim;

import static org.junit.jupiter.api.Assertions.*;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Speaks to the simulator exactly as open_abb's Python client abb.py does: its message strings
 * (format "+08.1f" for mm, "+08.5f" for quaternions, "+08.2f" for degrees), one recv per
 * request, replies split at ' ' and read with float().
 */
class TcpControllerServerTest {
    private SimulatedController controller;
    private TcpControllerServer server;

    @BeforeEach
    void start() throws Exception {
        controller = SimulatedControllerTest.controller(0);
        server = new TcpControllerServer(new ProtocolHandler(controller), InetAddress.getLoopbackAddress(), 0, null);
    }

    @AfterEach
    void stop() { server.close(); }

    /** Python's float(): surrounding whitespace ignored. */
    private static double pyFloat(String s) { return Double.parseDouble(s.strip()); }

    private static String exchange(Socket s, String msg) throws Exception {
        OutputStream out = s.getOutputStream();
        out.write(msg.getBytes(StandardCharsets.US_ASCII));
        out.flush();
        InputStream in = s.getInputStream();
        byte[] buf = new byte[4096];
        StringBuilder sb = new StringBuilder();
        s.setSoTimeout(2000);
        do {
            int n = in.read(buf);
            assertTrue(n > 0, "no reply to " + msg);
            sb.append(new String(buf, 0, n, StandardCharsets.US_ASCII));
        } while (!sb.toString().endsWith("\n"));
        return sb.toString();
    }

    @Test
    void abbPyMessages_fullSession_repliesParseAsAbbPyDoes() throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            // Robot.__init__: setTool, setWorkObject, setSpeed, setZone('z5')
            assertEquals("6 1 ", exchange(s, "06 +00000.0 +00000.0 +00100.0 +1.00000 +0.00000 +0.00000 +0.00000 #").replace("\n", ""));
            assertTrue(exchange(s, "07 +00000.0 +00000.0 +00000.0 +1.00000 +0.00000 +0.00000 +0.00000 #").startsWith("7 1"));
            assertTrue(exchange(s, "08 +00100.0 +0050.00 +00050.0 +0050.00 #").startsWith("8 1"));
            assertTrue(exchange(s, "09 0 +05.0000 +08.0000 +00.8000 #").startsWith("9 1"));
            // setJoints([10, -5, 20, 0, 30, 0])
            assertTrue(exchange(s, "02 +0010.00 -0005.00 +0020.00 +0000.00 +0030.00 +0000.00 #").startsWith("2 1"));
            // getJoints: r = [float(s) for s in data.split(' ')]; return r[2:8]
            String[] data = exchange(s, "04 #").split(" ");
            double[] r = Arrays.stream(data).mapToDouble(TcpControllerServerTest::pyFloat).toArray();
            assertEquals(4, r[0]);
            assertEquals(1, r[1]);
            assertArrayEquals(new double[] {10, -5, 20, 0, 30, 0}, Arrays.copyOfRange(r, 2, 8), 1e-9);
            // getCartesian: return [r[2:5], r[5:9]]; the tool is 100 mm along the flange z axis
            double[] c = Arrays.stream(exchange(s, "03 #").split(" ")).mapToDouble(TcpControllerServerTest::pyFloat).toArray();
            assertEquals(9, c.length);
            var expected = controller.robot().nominalFlange(controller.readJoints()).times(org.robopro.kinematics.Pose.translation(0, 0, 0.1));
            assertEquals(expected.x() * 1000, c[2], 1e-3);
            assertEquals(expected.z() * 1000, c[4], 1e-3);
            double[] q = expected.quaternion();
            assertEquals(q[0], c[5], 1e-6);
            // setCartesian([[900, 50, 1100], [1, 0, 0, 0]])
            assertTrue(exchange(s, "01 +00900.0 +00050.0 +01100.0 +1.00000 +0.00000 +0.00000 +0.00000 #").startsWith("1 1"));
            double[] c2 = Arrays.stream(exchange(s, "03 #").split(" ")).mapToDouble(TcpControllerServerTest::pyFloat).toArray();
            assertArrayEquals(new double[] {900, 50, 1100}, Arrays.copyOfRange(c2, 2, 5), 1e-3);
            // buffer: addBuffer x2, lenBuffer -> int(float(data[2])), executeBuffer
            exchange(s, "31 #");
            exchange(s, "30 +00850.0 +00050.0 +01100.0 +1.00000 +0.00000 +0.00000 +0.00000 #");
            exchange(s, "30 +00850.0 +00000.0 +01100.0 +1.00000 +0.00000 +0.00000 +0.00000 #");
            assertEquals(2, (int) pyFloat(exchange(s, "32 #").split(" ")[2]));
            assertTrue(exchange(s, "33 #").startsWith("33 1"));
            double[] c3 = Arrays.stream(exchange(s, "03 #").split(" ")).mapToDouble(TcpControllerServerTest::pyFloat).toArray();
            assertArrayEquals(new double[] {850, 0, 1100}, Arrays.copyOfRange(c3, 2, 5), 1e-3);
            // getRobotInfo: data[5:].split('*')
            assertEquals(3, exchange(s, "98 #").substring(5).split("\\*").length);
            assertTrue(exchange(s, "00 #").startsWith("0 1"));
        }
    }

    @Test
    void abbPyMessages_outOfLimitJoints_okZeroWithErrorCodeAndRobotStays() throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            // abb.py's default setJoints([0,0,0,0,90,0]): joint 5 is beyond the gantry's 80 deg
            String reply = exchange(s, "02 +0000.00 +0000.00 +0000.00 +0000.00 +0090.00 +0000.00 #");
            assertTrue(reply.startsWith("2 0 E110 "), reply);
            assertEquals(0, controller.motionsExecuted());
        }
    }

    @Test
    void malformedRequests_answeredWithErrorAndServerKeepsServing() throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            assertTrue(exchange(s, "02 1 2 3 #").startsWith("2 0 E100"));
            assertTrue(exchange(s, "02 a b c d e f #").startsWith("2 0 E102"));
            assertTrue(exchange(s, "02 NaN 0 0 0 0 0 #").startsWith("2 0 E102"));
            assertTrue(exchange(s, "77 #").startsWith("77 0 E101"));
            assertTrue(exchange(s, "xx #").contains(" 0 E100"));
            assertTrue(exchange(s, "06 0 0 0 2 0 0 0 #").startsWith("6 0 E102"), "non-unit quaternion");
            assertTrue(exchange(s, "46 0 AAAA #").startsWith("46 0 E202"), "chunk without download");
            assertTrue(exchange(s, "00 #").startsWith("0 1"));
        }
    }

    @Test
    void loggerPort_streamsCartesianAndJointMessagesAsLoggerMod() throws Exception {
        assertEquals(server.port() + 1, server.loggerPort());
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.loggerPort())) {
            s.setSoTimeout(2000);
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.US_ASCII));
            String[] a = in.readLine().split(" ");
            String[] b = in.readLine().split(" ");
            assertEquals("#", a[0]);
            assertEquals("0", a[1]);
            assertEquals(12, a.length, "# 0 date time clock x y z q1 q2 q3 q4");
            assertEquals("1", b[1]);
            assertEquals(11, b.length, "# 1 date time clock j1..j6");
            for (int i = 5; i < b.length; i++) pyFloat(b[i]);
        }
    }

    @Test
    void closeInstruction_dropsConnectionAndServerAcceptsNext() throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            s.getOutputStream().write("99 #".getBytes(StandardCharsets.US_ASCII));
            s.setSoTimeout(2000);
            assertEquals(-1, s.getInputStream().read());
        }
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            assertTrue(exchange(s, "00 #").startsWith("0 1"));
        }
    }
}
