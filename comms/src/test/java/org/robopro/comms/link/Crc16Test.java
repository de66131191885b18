package org.robopro.comms.link;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.junit.jupiter.api.Test;

class Crc16Test {
    @Test
    void ccitt_checkString_is29B1() {
        byte[] d = "123456789".getBytes(StandardCharsets.US_ASCII);
        assertEquals(0x29B1, Crc16.ccitt(d, 0, d.length));
    }

    @Test
    void ccitt_randomData_tableMatchesBitwiseReference() {
        Random rnd = new Random(3);
        for (int k = 0; k < 200; k++) {
            byte[] d = new byte[rnd.nextInt(300)];
            rnd.nextBytes(d);
            assertEquals(Crc16.ccittReference(d, 0, d.length), Crc16.ccitt(d, 0, d.length));
        }
    }
}
