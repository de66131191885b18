package org.robopro.comms.link;

/**
 * One link-layer frame: DATA carries a payload with the sender's session id and sequence
 * number; ACK acknowledges (session, seq); NAK asks the peer to resend its outstanding frame.
 */
public record Frame(Type type, int session, int seq, byte[] payload) {
    public enum Type {
        DATA('D'), ACK('A'), NAK('N');

        final byte wire;

        Type(char c) { this.wire = (byte) c; }

        static Type of(byte b) {
            for (Type t : values()) if (t.wire == b) return t;
            return null;
        }
    }

    public Frame {
        if (session < 0 || session > 0xFFFF || seq < 0 || seq > 0xFFFF)
            throw new IllegalArgumentException("session/seq outside 16 bits: " + session + ", " + seq);
    }
}
