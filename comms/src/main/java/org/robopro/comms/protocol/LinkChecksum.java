package org.robopro.comms.protocol;

import java.nio.charset.StandardCharsets;

/**
 * Checksum mode of the robopro protocol on TCP (docs/controller-link.md). TCP's own 16-bit
 * checksum lets rare corruption through, and open_abb's text carries none, so a robopro client
 * asks for this mode per connection with {@code 40 crc #}; a robopro controller answers its HELLO
 * reply followed by {@code crc} (sealed as below) and from then on, on that connection only:
 * <ul>
 * <li>each request is {@code NN p1 ... *XXXXXXXX #}, XXXXXXXX the CRC-32 (hex) of the text before
 *     the {@code *}; a request that fails it is not executed and answered
 *     {@code NN 0 E103 ...}, which the client sends again;</li>
 * <li>each reply is {@code NN ok data *XXXXXXXX}, the CRC-32 of the text before {@code " *"}
 *     followed by the request's checksum, which binds the reply to its request (a stale or
 *     duplicated reply to another request fails it); the client treats a reply without a valid
 *     one as not received and asks again.</li>
 * </ul>
 * Clients that never send {@code 40 crc #} (open_abb's own) see the protocol unchanged; a plain
 * SERVER.mod answers {@code 40 0} and the client stays in plain mode.
 */
public final class LinkChecksum {
    /** The HELLO parameter and reply token that switch checksum mode on. */
    public static final String MODE = "crc";

    private LinkChecksum() { }

    /** The request that asks for checksum mode. */
    public static String hello() { return OpenAbb.request(OpenAbb.HELLO, MODE); }

    /** True for the request {@code 40 crc #} (any spacing). */
    public static boolean isHello(String request) {
        return request.strip().replaceAll("\\s+", " ").equals(hello());
    }

    private static String crc(String text) {
        return Checksums.hex(Checksums.crc32(text.getBytes(StandardCharsets.ISO_8859_1)));
    }

    /** Client: "NN p1 ... #" becomes "NN p1 ... *XXXXXXXX #". */
    public static String sealRequest(String request) {
        int hash = request.lastIndexOf('#');
        String body = hash < 0 ? request : request.substring(0, hash);
        return body + "*" + crc(body) + " #";
    }

    /** The checksum token of a sealed request (the key its reply is sealed with), or "". */
    public static String key(String sealedRequest) {
        int hash = sealedRequest.lastIndexOf('#');
        int star = hash < 0 ? -1 : sealedRequest.lastIndexOf('*', hash);
        return star < 0 ? "" : sealedRequest.substring(star + 1, hash).strip();
    }

    /** Controller: the plain request ("NN p1 ... #") when its checksum holds, else null. */
    public static String open(String request) {
        int hash = request.lastIndexOf('#');
        int star = hash < 0 ? -1 : request.lastIndexOf('*', hash);
        if (star < 0) return null;
        String body = request.substring(0, star);
        String token = request.substring(star + 1, hash).strip();
        return token.equals(crc(body)) ? body + "#" : null;
    }

    /** Controller: a reply with its checksum (over the reply and the request's {@code key}) appended. */
    public static String seal(String reply, String key) {
        return reply + " *" + crc(reply + key);
    }

    /** Client: the reply without its checksum when the checksum (with the request's {@code key}) holds, else null. */
    public static String unseal(String line, String key) {
        String t = line.endsWith("\r") ? line.substring(0, line.length() - 1) : line;
        int star = t.lastIndexOf(" *");
        if (star < 0 || t.length() - star - 2 != 8) return null;
        String body = t.substring(0, star);
        return t.substring(star + 2).equals(crc(body + key)) ? body : null;
    }

    /** The instruction number a (possibly damaged) request starts with, or 0. */
    public static int instruction(String request) {
        String t = request.strip();
        int i = 0;
        while (i < t.length() && i < 3 && Character.isDigit(t.charAt(i))) i++;
        return i == 0 ? 0 : Integer.parseInt(t.substring(0, i));
    }
}
