package org.robopro.comms.link;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robopro.comms.CommsException;

class FramedLinkTest {
    private static final FramedLink.Options FAST = new FramedLink.Options(Duration.ofMillis(20), 12);

    @Test
    void send_lossyLineBothWays_eachMessageDeliveredOnceInOrder() throws Exception {
        MemoryByteLink[] pair = MemoryByteLink.pair();
        FaultInjector fa = FaultInjector.uniform(1, 0.15, 15), fb = FaultInjector.uniform(2, 0.15, 15);
        try (FramedLink a = new FramedLink(pair[0], FAST, fa); FramedLink b = new FramedLink(pair[1], FAST, fb)) {
            int n = 600;
            Thread t = new Thread(() -> {
                for (int i = 0; i < n; i++) b.send(("b" + i).getBytes(StandardCharsets.US_ASCII));
            });
            t.start();
            List<String> atB = new ArrayList<>(), atA = new ArrayList<>();
            for (int i = 0; i < n; i++) a.send(("a" + i).getBytes(StandardCharsets.US_ASCII));
            t.join(60_000);
            byte[] m;
            while ((m = b.receive(Duration.ofMillis(200))) != null) atB.add(new String(m, StandardCharsets.US_ASCII));
            while ((m = a.receive(Duration.ofMillis(200))) != null) atA.add(new String(m, StandardCharsets.US_ASCII));
            for (int i = 0; i < n; i++) {
                assertEquals("a" + i, atB.get(i));
                assertEquals("b" + i, atA.get(i));
            }
            assertEquals(n, atB.size());
            assertEquals(n, atA.size());
            assertTrue(a.retransmissions() > 0 && b.duplicatesSuppressed() + a.duplicatesSuppressed() > 0,
                    "faults must have forced retransmissions and duplicates: " + a.stats() + " / " + b.stats());
        }
    }

    @Test
    void send_peerSilent_failsWithClearErrorThenNewSessionIsAccepted() throws Exception {
        MemoryByteLink[] pair = MemoryByteLink.pair();
        FaultInjector dropAll = new FaultInjector(1, 1.0, 0, 0, 0, 0);
        try (FramedLink a = new FramedLink(pair[0], new FramedLink.Options(Duration.ofMillis(10), 3), null);
             FramedLink b = new FramedLink(pair[1], FAST, dropAll)) { // b's ACKs never arrive
            CommsException.LinkDown e = assertThrows(CommsException.LinkDown.class, () -> a.send("x".getBytes()));
            assertTrue(e.getMessage().contains("no acknowledgement"), e.getMessage());
            assertArrayEquals("x".getBytes(), b.receive(Duration.ofSeconds(1)));
            assertNull(b.receive(Duration.ofMillis(100)), "retransmissions of x must not be delivered again");
        }
    }

    @Test
    void receive_peerClosed_reportsLinkDown() throws Exception {
        MemoryByteLink[] pair = MemoryByteLink.pair();
        try (FramedLink a = new FramedLink(pair[0], FAST, null)) {
            pair[1].close();
            Thread.sleep(100);
            assertThrows(CommsException.LinkDown.class, () -> a.receive(Duration.ofMillis(100)));
        }
    }
}
