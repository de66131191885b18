package org.robopro.comms.sim;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Base64;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.comms.protocol.Checksums;

class ProtocolHandlerTest {

    @Test
    void handle_randomGarbageAndMutatedRequests_alwaysAnswersNeverThrows() {
        ProtocolHandler h = new ProtocolHandler(TestSupport.gantryController(0));
        ProtocolHandler.Session s = h.newSession();
        Random rnd = new Random(12);
        String[] seeds = {"02 10 0 0 0 20 0 #", "01 800 0 1000 1 0 0 0 #", "45 p 10 00000000 #", "46 0 AAAA #", "08 100 50 #",
                "09 0 5 8 0.8 #", "42 17 1 2 3 4 5 6 #", "49 p 0 #", "50 1 p #", "43 #"};
        String alphabet = "0123456789 #.-+eE,abcXYZ\n\t\u00e9=/";
        for (int k = 0; k < 5000; k++) {
            StringBuilder sb = new StringBuilder(seeds[rnd.nextInt(seeds.length)]);
            int edits = rnd.nextInt(4);
            for (int e = 0; e < edits && sb.length() > 0; e++) {
                int i = rnd.nextInt(sb.length());
                switch (rnd.nextInt(3)) {
                    case 0 -> sb.deleteCharAt(i);
                    case 1 -> sb.insert(i, alphabet.charAt(rnd.nextInt(alphabet.length())));
                    default -> sb.setCharAt(i, alphabet.charAt(rnd.nextInt(alphabet.length())));
                }
            }
            String reply = h.handle(s, sb.toString());
            if (reply == null) continue; // 99: close
            assertTrue(reply.matches("\\d+ [01] .*"), "bad reply '" + reply + "' to '" + sb + "'");
            assertFalse(reply.contains(" 0 E300"), "internal error for '" + sb + "': " + reply);
        }
        assertEquals("0 1 ", h.handle(s, "00 #"));
    }

    @Test
    void handle_downloadInterruptedByNewSession_nothingStored() {
        SimulatedController c = TestSupport.gantryController(0);
        ProtocolHandler h = new ProtocolHandler(c);
        byte[] prog = TestSupport.squareProgram();
        ProtocolHandler.Session s1 = h.newSession();
        assertTrue(h.handle(s1, "45 square " + prog.length + " " + Checksums.hex(Checksums.crc32(prog)) + " #").startsWith("45 1"));
        String half = Base64.getEncoder().encodeToString(java.util.Arrays.copyOf(prog, 100));
        assertTrue(h.handle(s1, "46 0 " + half + " #").startsWith("46 1 100"));
        ProtocolHandler.Session s2 = h.newSession(); // the link dropped and came back
        assertTrue(h.handle(s2, "47 #").startsWith("47 0 E202"));
        assertTrue(c.listPrograms().isEmpty());
    }

    @Test
    void handle_commitWithWrongChecksum_refusedNothingStored() {
        SimulatedController c = TestSupport.gantryController(0);
        ProtocolHandler h = new ProtocolHandler(c);
        ProtocolHandler.Session s = h.newSession();
        byte[] prog = TestSupport.squareProgram();
        h.handle(s, "45 square " + prog.length + " " + Checksums.hex(Checksums.crc32(prog) ^ 0x10) + " #");
        for (int off = 0; off < prog.length; off += 400)
            h.handle(s, "46 " + off + " " + Base64.getEncoder().encodeToString(java.util.Arrays.copyOfRange(prog, off, Math.min(prog.length, off + 400))) + " #");
        assertTrue(h.handle(s, "47 #").startsWith("47 0 E201"));
        assertTrue(c.listPrograms().isEmpty());
    }
}
