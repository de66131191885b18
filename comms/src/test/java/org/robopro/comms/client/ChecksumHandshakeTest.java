package org.robopro.comms.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.robopro.comms.CommsException;

/** The checksum handshake never falls back to unchecked text because of damage. */
class ChecksumHandshakeTest {
    /** A server answering every request with {@code reply}. */
    static ServerSocket server(String reply) throws Exception {
        ServerSocket ss = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        Thread t = new Thread(() -> {
            while (!ss.isClosed()) {
                try (Socket s = ss.accept()) {
                    InputStream in = s.getInputStream();
                    OutputStream out = s.getOutputStream();
                    int c;
                    while ((c = in.read()) >= 0) {
                        if (c == '#') {
                            out.write(reply.getBytes(StandardCharsets.ISO_8859_1));
                            out.flush();
                        }
                    }
                } catch (Exception e) {
                    // next client
                }
            }
        });
        t.setDaemon(true);
        t.start();
        return ss;
    }

    @Test
    void damagedHelloRefusedByARoboproController_isAFailureToRetry_notPlainMode() throws Exception {
        // "40 crd #" (one damaged byte) is refused by a robopro controller with an error code.
        try (ServerSocket ss = server("40 0 E100 HELLO takes no parameters\n");
             TcpRequestChannel ch = new TcpRequestChannel("127.0.0.1", ss.getLocalPort(), Duration.ofSeconds(2), Duration.ofMillis(30))) {
            assertThrows(CommsException.Protocol.class, () -> ch.exchange("00 #", 0, Duration.ofSeconds(2)));
            assertFalse(ch.checksummed());
        }
    }

    @Test
    void plainServerMod_answersExactly40Zero_andTheLinkStaysPlain() throws Exception {
        try (ServerSocket ss = server("40 0 ");
             TcpRequestChannel ch = new TcpRequestChannel("127.0.0.1", ss.getLocalPort(), Duration.ofSeconds(2), Duration.ofMillis(30))) {
            assertEquals("40 0 ", ch.exchange("00 #", 0, Duration.ofSeconds(2)));
            assertFalse(ch.checksummed());
        }
    }
}
