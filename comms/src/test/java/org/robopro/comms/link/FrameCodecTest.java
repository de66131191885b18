package org.robopro.comms.link;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class FrameCodecTest {
    private final List<Frame> frames = new ArrayList<>();
    private final List<String> errors = new ArrayList<>();
    private final FrameCodec.Decoder decoder = new FrameCodec.Decoder(frames::add, errors::add);

    @Test
    void encodeDecode_randomPayloadsWithMarkerBytes_roundTrip() {
        Random rnd = new Random(1);
        for (int k = 0; k < 300; k++) {
            byte[] p = new byte[rnd.nextInt(600)];
            rnd.nextBytes(p);
            if (p.length > 3) { p[0] = FrameCodec.STX; p[1] = FrameCodec.ETX; p[2] = FrameCodec.DLE; }
            Frame f = new Frame(Frame.Type.DATA, rnd.nextInt(0x10000), rnd.nextInt(0x10000), p);
            byte[] wire = FrameCodec.encode(f);
            for (int i = 1; i < wire.length - 1; i++)
                assertTrue(wire[i] != FrameCodec.STX && wire[i] != FrameCodec.ETX, "marker inside a frame");
            decoder.feed(wire, 0, wire.length);
            Frame g = frames.remove(0);
            assertEquals(f.session(), g.session());
            assertEquals(f.seq(), g.seq());
            assertArrayEquals(p, g.payload());
        }
        assertTrue(errors.isEmpty());
    }

    @Test
    void decode_noiseBetweenFrames_ignored() {
        byte[] f1 = FrameCodec.encode(new Frame(Frame.Type.ACK, 1, 2, null));
        decoder.feed(new byte[] {0x55, 0x03, 0x10, 0x7F}, 0, 4);
        decoder.feed(f1, 0, f1.length);
        assertEquals(1, frames.size());
        assertEquals(Frame.Type.ACK, frames.get(0).type());
    }

    @Test
    void decode_everySingleByteCorruption_neverYieldsAWrongFrame() {
        Random rnd = new Random(2);
        byte[] payload = "42 12345 10.0 -5.0 20.0 0.0 30.0 0.0 #".getBytes();
        Frame f = new Frame(Frame.Type.DATA, 777, 5, payload);
        byte[] wire = FrameCodec.encode(f);
        int wrong = 0;
        for (int i = 0; i < wire.length; i++) {
            for (int k = 0; k < 8; k++) {
                byte[] c = wire.clone();
                c[i] ^= (byte) (1 + rnd.nextInt(255));
                frames.clear();
                decoder.feed(c, 0, c.length);
                decoder.feed(FrameCodec.STX); // let a frame cut at ETX be flushed
                for (Frame g : frames)
                    if (g.session() != 777 || g.seq() != 5 || !java.util.Arrays.equals(g.payload(), payload)) wrong++;
            }
        }
        assertEquals(0, wrong);
    }
}
