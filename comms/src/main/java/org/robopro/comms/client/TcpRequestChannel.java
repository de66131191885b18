package org.robopro.comms.client;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.robopro.comms.CommsException;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.protocol.LinkChecksum;
import org.robopro.comms.protocol.OpenAbb;

/**
 * The open_abb protocol over TCP. SERVER.mod sends each reply in one SocketSend with no
 * terminator; robopro's simulator ends replies with '\n'. A reply is complete at '\n', or when
 * it is "NN ok " (ends in the space SERVER.mod puts after the ok flag when there is no data),
 * or when data has arrived and the line stays quiet for {@code quietTime}.
 *
 * <p>After a timeout the socket is closed, so a late reply can never be taken for the answer
 * to the next request; the next exchange reconnects.
 *
 * <p>With checksums on (the default), each new connection first asks for the robopro protocol's
 * checksum mode ({@link LinkChecksum}); a robopro controller accepts and from then on requests
 * and replies carry a CRC-32, and a damaged one is a {@link CommsException.Protocol} (the
 * invoker asks again) instead of a wrong value. A plain SERVER.mod declines and the link stays
 * plain open_abb.
 */
public final class TcpRequestChannel implements RequestChannel {
    private final String host;
    private final int port;
    private final Duration connectTimeout;
    private final Duration quietTime;
    private final boolean checksums;
    private Boolean crcMode; // null until the connection's handshake
    private boolean serverChecksums; // the controller accepted checksum mode once: it must on every connection
    private Socket socket;
    private InputStream in;
    private OutputStream out;

    public TcpRequestChannel(String host, int port, Duration connectTimeout, Duration quietTime) {
        this(host, port, connectTimeout, quietTime, true);
    }

    /** {@code checksums} false never asks for checksum mode (the plain open_abb exchange). */
    public TcpRequestChannel(String host, int port, Duration connectTimeout, Duration quietTime, boolean checksums) {
        this.host = host;
        this.port = port;
        this.connectTimeout = connectTimeout;
        this.quietTime = quietTime;
        this.checksums = checksums;
    }

    /** True when this connection runs in checksum mode (after its first exchange). */
    public boolean checksummed() { return Boolean.TRUE.equals(crcMode); }

    public TcpRequestChannel(String host, int port) {
        this(host, port, Duration.ofSeconds(3), Duration.ofMillis(30));
    }

    /** Parses "HOST:PORT". */
    public static TcpRequestChannel parse(String hostPort) {
        int i = hostPort.lastIndexOf(':');
        if (i <= 0 || i == hostPort.length() - 1)
            throw new IllegalArgumentException("'" + hostPort + "' is not HOST:PORT");
        int port;
        try {
            port = Integer.parseInt(hostPort.substring(i + 1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("port in '" + hostPort + "' is not a number");
        }
        if (port < 1 || port > 65535) throw new IllegalArgumentException("port " + port + " outside 1..65535");
        return new TcpRequestChannel(hostPort.substring(0, i), port);
    }

    @Override
    public String describe() { return "tcp " + host + ":" + port + (checksummed() ? " (crc)" : ""); }

    private void connect() {
        if (socket != null) return;
        Socket s = new Socket();
        try {
            s.setTcpNoDelay(true);
            s.connect(new InetSocketAddress(host, port), (int) connectTimeout.toMillis());
            socket = s;
            in = s.getInputStream();
            out = s.getOutputStream();
        } catch (IOException e) {
            try {
                s.close();
            } catch (IOException ignored) {
                // failed anyway
            }
            throw new CommsException.LinkDown("cannot connect to controller at " + host + ":" + port + ": " + e.getMessage(), e);
        }
    }

    @Override
    public String exchange(String request, int instruction, Duration timeout) {
        connect();
        try {
            if (crcMode == null) handshake(timeout);
            while (in.available() > 0) in.skip(in.available()); // stale bytes (e.g. a duplicated reply)
            boolean crc = crcMode;
            String sent = crc ? LinkChecksum.sealRequest(request) : request;
            out.write(sent.getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
            String reply = readReply(timeout, request, crc);
            if (!crc) return reply;
            String plain = LinkChecksum.unseal(reply, LinkChecksum.key(sent));
            if (plain == null && LinkChecksum.unseal(reply, "") != null && reply.contains(" " + ErrorCode.LINK_CHECKSUM.wire() + " "))
                throw new CommsException.Protocol("request '" + clip(request) + "' arrived damaged at the controller (not executed)");
            if (plain == null) {
                disconnect(); // what follows on this connection cannot be trusted either
                throw new CommsException.Protocol("reply to '" + clip(request) + "' failed its checksum (damaged on the link)");
            }
            return plain;
        } catch (SocketTimeoutException e) {
            disconnect();
            throw new CommsException.Timeout("controller at " + host + ":" + port + " did not answer '" + clip(request)
                    + "' within " + timeout.toMillis() + " ms");
        } catch (IOException e) {
            disconnect();
            throw new CommsException.LinkDown("link to " + host + ":" + port + " failed during '" + clip(request) + "': " + e.getMessage(), e);
        }
    }

    /** Asks a new connection for checksum mode; a garbled answer is a protocol failure (asked again). */
    private void handshake(Duration timeout) throws IOException {
        if (!checksums) {
            crcMode = false;
            return;
        }
        out.write(LinkChecksum.hello().getBytes(StandardCharsets.ISO_8859_1));
        out.flush();
        String reply = readReply(timeout, LinkChecksum.hello(), false).strip();
        String plain = LinkChecksum.unseal(reply, "");
        if (plain != null && plain.startsWith(OpenAbb.HELLO + " 1 ") && plain.endsWith(" " + LinkChecksum.MODE)) {
            crcMode = true;
            serverChecksums = true;
        } else if (reply.equals(OpenAbb.HELLO + " 0") && !serverChecksums) {
            crcMode = false; // plain open_abb (SERVER.mod answers exactly "40 0"): no checksum mode
        } else {
            // Anything else is damage (a robopro controller that refused a damaged "40 crc #", or one
            // that spoke checksums before): never fall back to unchecked text, ask again.
            disconnect();
            throw new CommsException.Protocol("the checksum handshake with " + host + ":" + port + " was garbled");
        }
    }

    private String readReply(Duration timeout, String request, boolean wholeLine) throws IOException {
        long deadline = System.nanoTime() + timeout.toNanos();
        StringBuilder sb = new StringBuilder();
        byte[] buf = new byte[4096];
        while (true) {
            long left = (deadline - System.nanoTime()) / 1_000_000;
            boolean haveData = sb.toString().strip().split("\\s+").length >= 3;
            if (left <= 0) {
                if (haveData && !wholeLine) return sb.toString();
                throw new SocketTimeoutException();
            }
            socket.setSoTimeout((int) Math.max(1, haveData && !wholeLine ? Math.min(left, quietTime.toMillis()) : left));
            int n;
            try {
                n = in.read(buf);
            } catch (SocketTimeoutException e) {
                if (haveData && !wholeLine) return sb.toString(); // SERVER.mod: no terminator, the line went quiet
                throw e;
            }
            if (n < 0) throw new IOException("controller closed the connection");
            sb.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            int nl = sb.indexOf("\n");
            if (nl >= 0) return sb.substring(0, nl);
            String t = sb.toString();
            if (!wholeLine && t.endsWith(" ") && t.strip().split("\\s+").length == 2) return t; // "NN ok " with no data
            if (sb.length() > 65536) throw new IOException("reply to '" + clip(request) + "' longer than 64 KiB");
        }
    }

    private static String clip(String s) {
        String t = s.strip();
        return t.length() > 48 ? t.substring(0, 48) + "..." : t;
    }

    private void disconnect() {
        if (socket != null) {
            try {
                socket.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        socket = null;
        in = null;
        out = null;
        crcMode = null;
    }

    @Override
    public void reconnect() {
        disconnect();
        connect();
    }

    @Override
    public void close() { disconnect(); }
}
