package org.robopro.comms.link;

import java.io.ByteArrayOutputStream;
import java.util.function.Consumer;

/**
 * Byte framing for an unreliable serial line: STX (0x02) ... ETX (0x03), with DLE (0x10)
 * stuffing (a STX, ETX or DLE inside the frame is sent as DLE followed by the byte XOR 0x20),
 * and a CRC-16/CCITT over the frame body. Body: type (1), session (2), seq (2), payload length
 * (2), payload, CRC (2); multi-byte fields big-endian.
 *
 * <p>The {@link Decoder} resynchronises at every STX, so garbage between frames and frames
 * broken by a lost byte cost only those frames.
 */
public final class FrameCodec {
    public static final byte STX = 0x02, ETX = 0x03, DLE = 0x10;
    public static final int MAX_PAYLOAD = 2048;

    private FrameCodec() { }

    public static byte[] encode(Frame f) {
        byte[] p = f.payload() == null ? new byte[0] : f.payload();
        if (p.length > MAX_PAYLOAD) throw new IllegalArgumentException("payload of " + p.length + " bytes > " + MAX_PAYLOAD);
        byte[] body = new byte[7 + p.length + 2];
        body[0] = f.type().wire;
        body[1] = (byte) (f.session() >>> 8);
        body[2] = (byte) f.session();
        body[3] = (byte) (f.seq() >>> 8);
        body[4] = (byte) f.seq();
        body[5] = (byte) (p.length >>> 8);
        body[6] = (byte) p.length;
        System.arraycopy(p, 0, body, 7, p.length);
        int crc = Crc16.ccitt(body, 0, 7 + p.length);
        body[7 + p.length] = (byte) (crc >>> 8);
        body[8 + p.length] = (byte) crc;
        ByteArrayOutputStream out = new ByteArrayOutputStream(body.length + 8);
        out.write(STX);
        for (byte b : body) {
            if (b == STX || b == ETX || b == DLE) {
                out.write(DLE);
                out.write(b ^ 0x20);
            } else {
                out.write(b);
            }
        }
        out.write(ETX);
        return out.toByteArray();
    }

    /** Incremental decoder: feed it bytes as they come; it reports frames and framing errors. */
    public static final class Decoder {
        private final Consumer<Frame> frames;
        private final Consumer<String> errors;
        private final byte[] buf = new byte[2 * (MAX_PAYLOAD + 16)];
        private int len = -1; // -1: outside a frame
        private boolean escape;

        public Decoder(Consumer<Frame> frames, Consumer<String> errors) {
            this.frames = frames;
            this.errors = errors;
        }

        public void feed(byte[] data, int off, int n) {
            for (int i = off; i < off + n; i++) feed(data[i]);
        }

        public void feed(byte b) {
            if (b == STX) {
                if (len > 0) errors.accept("frame cut off by a new start marker");
                len = 0;
                escape = false;
                return;
            }
            if (len < 0) return; // noise between frames
            if (b == ETX) {
                finish();
                len = -1;
                return;
            }
            if (b == DLE) {
                escape = true;
                return;
            }
            if (escape) {
                b ^= 0x20;
                escape = false;
            }
            if (len == buf.length) {
                errors.accept("frame longer than " + buf.length + " bytes");
                len = -1;
                return;
            }
            buf[len++] = b;
        }

        private void finish() {
            if (escape) {
                errors.accept("frame ends inside an escape");
                return;
            }
            if (len < 9) {
                errors.accept("frame of " + len + " bytes is too short");
                return;
            }
            int plen = ((buf[5] & 0xFF) << 8) | (buf[6] & 0xFF);
            if (plen != len - 9) {
                errors.accept("frame length field " + plen + " does not match " + (len - 9) + " payload bytes");
                return;
            }
            int crc = ((buf[len - 2] & 0xFF) << 8) | (buf[len - 1] & 0xFF);
            if (crc != Crc16.ccitt(buf, 0, len - 2)) {
                errors.accept("CRC mismatch");
                return;
            }
            Frame.Type t = Frame.Type.of(buf[0]);
            if (t == null) {
                errors.accept("unknown frame type " + (buf[0] & 0xFF));
                return;
            }
            byte[] p = new byte[plen];
            System.arraycopy(buf, 7, p, 0, plen);
            frames.accept(new Frame(t, ((buf[1] & 0xFF) << 8) | (buf[2] & 0xFF), ((buf[3] & 0xFF) << 8) | (buf[4] & 0xFF), p));
        }
    }
}
