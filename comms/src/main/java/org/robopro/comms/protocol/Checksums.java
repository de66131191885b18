package org.robopro.comms.protocol;

import java.util.zip.CRC32;

/** CRC-32 (ISO-HDLC, as java.util.zip) of program texts, written as 8 lowercase hex digits. */
public final class Checksums {
    private Checksums() { }

    public static long crc32(byte[] bytes) {
        CRC32 c = new CRC32();
        c.update(bytes);
        return c.getValue();
    }

    public static String hex(long crc) { return String.format("%08x", crc); }

    /** Parses 8 hex digits; returns -1 if malformed. */
    public static long parseHex(String s) {
        if (s == null || !s.matches("[0-9a-fA-F]{8}")) return -1;
        return Long.parseLong(s, 16);
    }
}
