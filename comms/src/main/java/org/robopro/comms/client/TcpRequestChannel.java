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

/**
 * The open_abb protocol over TCP. SERVER.mod sends each reply in one SocketSend with no
 * terminator; robopro's simulator ends replies with '\n'. A reply is complete at '\n', or when
 * it is "NN ok " (ends in the space SERVER.mod puts after the ok flag when there is no data),
 * or when data has arrived and the line stays quiet for {@code quietTime}.
 *
 * <p>After a timeout the socket is closed, so a late reply can never be taken for the answer
 * to the next request; the next exchange reconnects.
 */
public final class TcpRequestChannel implements RequestChannel {
    private final String host;
    private final int port;
    private final Duration connectTimeout;
    private final Duration quietTime;
    private Socket socket;
    private InputStream in;
    private OutputStream out;

    public TcpRequestChannel(String host, int port, Duration connectTimeout, Duration quietTime) {
        this.host = host;
        this.port = port;
        this.connectTimeout = connectTimeout;
        this.quietTime = quietTime;
    }

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
    public String describe() { return "tcp " + host + ":" + port; }

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
            while (in.available() > 0) in.skip(in.available()); // stale bytes (e.g. a duplicated reply)
            out.write(request.getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
            return readReply(timeout, request);
        } catch (SocketTimeoutException e) {
            disconnect();
            throw new CommsException.Timeout("controller at " + host + ":" + port + " did not answer '" + clip(request)
                    + "' within " + timeout.toMillis() + " ms");
        } catch (IOException e) {
            disconnect();
            throw new CommsException.LinkDown("link to " + host + ":" + port + " failed during '" + clip(request) + "': " + e.getMessage(), e);
        }
    }

    private String readReply(Duration timeout, String request) throws IOException {
        long deadline = System.nanoTime() + timeout.toNanos();
        StringBuilder sb = new StringBuilder();
        byte[] buf = new byte[4096];
        while (true) {
            long left = (deadline - System.nanoTime()) / 1_000_000;
            boolean haveData = sb.toString().strip().split("\\s+").length >= 3;
            if (left <= 0) {
                if (haveData) return sb.toString();
                throw new SocketTimeoutException();
            }
            socket.setSoTimeout((int) Math.max(1, haveData ? Math.min(left, quietTime.toMillis()) : left));
            int n;
            try {
                n = in.read(buf);
            } catch (SocketTimeoutException e) {
                if (haveData) return sb.toString(); // SERVER.mod: no terminator, the line went quiet
                throw e;
            }
            if (n < 0) throw new IOException("controller closed the connection");
            sb.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            int nl = sb.indexOf("\n");
            if (nl >= 0) return sb.substring(0, nl);
            String t = sb.toString();
            if (t.endsWith(" ") && t.strip().split("\\s+").length == 2) return t; // "NN ok " with no data
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
    }

    @Override
    public void reconnect() {
        disconnect();
        connect();
    }

    @Override
    public void close() { disconnect(); }
}
