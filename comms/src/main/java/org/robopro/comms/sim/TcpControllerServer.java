package org.robopro.comms.sim;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.protocol.LinkChecksum;
import org.robopro.comms.protocol.OpenAbb;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated controller on TCP, as RAPID/SERVER.mod and LOGGER.mod serve it: the motion
 * server on {@code port} (requests "NN ... #", one reply each) and the logger stream on
 * {@code port + 1} ("# 0 date time clock x y z q1 q2 q3 q4" and "# 1 date time clock j1..j6",
 * every 0.1 s). Several clients may connect; the controller serialises their requests.
 *
 * <p>Fault injection for tests: replies dropped, corrupted, duplicated or delayed, and a
 * connection cut after a number of program-download chunks.
 */
public final class TcpControllerServer implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(TcpControllerServer.class);
    private static final AtomicInteger THREADS = new AtomicInteger();

    private final ProtocolHandler handler;
    private final FaultInjector faults;
    private final FaultInjector requestFaults;
    private final ServerSocket motion;
    private final ServerSocket logger;
    private final Set<Socket> clients = ConcurrentHashMap.newKeySet();
    /** One thread per open connection, at most {@link #MAX_CONNECTIONS} (plus the two accept loops). */
    private final java.util.concurrent.ExecutorService connections = java.util.concurrent.Executors.newFixedThreadPool(MAX_CONNECTIONS, r -> {
        Thread t = new Thread(r, "robopro-sim-conn-" + THREADS.incrementAndGet());
        t.setDaemon(true);
        return t;
    });
    private final AtomicInteger cutAfterChunks = new AtomicInteger(-1);
    private final AtomicInteger requests = new AtomicInteger();
    private volatile boolean closed;
    private final long startNanos = System.nanoTime();

    /**
     * Binds the motion server to {@code host:port} and the logger to {@code port + 1}; with port 0,
     * finds a free pair.
     */
    public TcpControllerServer(ProtocolHandler handler, InetAddress host, int port, FaultInjector faults) throws IOException {
        this(handler, host, port, faults, null);
    }

    /**
     * As above, with faults also on the requests as they arrive ({@code requestFaults}: dropped,
     * corrupted, duplicated, delayed, or the connection cut), for soak tests of both directions.
     */
    public TcpControllerServer(ProtocolHandler handler, InetAddress host, int port, FaultInjector faults,
                               FaultInjector requestFaults) throws IOException {
        this.handler = handler;
        this.faults = faults == null ? FaultInjector.none() : faults;
        this.requestFaults = requestFaults == null ? FaultInjector.none() : requestFaults;
        ServerSocket m = null, l = null;
        for (int attempt = 0; attempt < 50 && l == null; attempt++) {
            m = new ServerSocket();
            m.setReuseAddress(true);
            m.bind(new InetSocketAddress(host, port), 50);
            try {
                l = new ServerSocket();
                l.setReuseAddress(true);
                l.bind(new InetSocketAddress(host, m.getLocalPort() + 1), 50);
            } catch (IOException e) {
                l.close();
                l = null;
                m.close();
                if (port != 0) throw new IOException("logger port " + (port + 1) + " (motion port + 1) is taken: " + e.getMessage(), e);
            }
        }
        if (l == null) throw new IOException("found no free pair of ports (motion, motion + 1) on " + host);
        this.motion = m;
        this.logger = l;
        daemon("robopro-sim-accept", () -> acceptLoop(motion, this::serveMotion)).start();
        daemon("robopro-sim-logger-accept", () -> acceptLoop(logger, this::serveLogger)).start();
        LOG.info("simulated controller listening on {}:{} (logger on {})", host.getHostAddress(), port(), port() + 1);
    }

    public int port() { return motion.getLocalPort(); }

    public int loggerPort() { return logger.getLocalPort(); }

    /** Requests served so far. */
    public int requests() { return requests.get(); }

    /** Test fault: cut the connection (without replying) when the n-th next download chunk arrives. */
    public void cutConnectionAtDownloadChunk(int n) { cutAfterChunks.set(n); }

    /** Drops every client connection (the server keeps listening): a dropped link. */
    public void dropClients() {
        for (Socket s : clients) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
    }

    private static Thread daemon(String name, Runnable r) {
        Thread t = new Thread(r, name + "-" + THREADS.incrementAndGet());
        t.setDaemon(true);
        return t;
    }

    private interface Serve { void serve(Socket s) throws IOException; }

    /** Most connections served at once (motion and logger together); more are refused with a reply. */
    public static final int MAX_CONNECTIONS = 64;

    private void acceptLoop(ServerSocket server, Serve serve) {
        while (!closed) {
            try {
                Socket s = server.accept();
                s.setTcpNoDelay(true);
                if (clients.size() >= MAX_CONNECTIONS) {
                    refuse(s);
                    continue;
                }
                clients.add(s);
                connections.execute(() -> {
                    try {
                        serve.serve(s);
                    } catch (IOException e) {
                        LOG.debug("connection from {} ended: {}", s.getRemoteSocketAddress(), e.getMessage());
                    } finally {
                        clients.remove(s);
                        try {
                            s.close();
                        } catch (IOException ignored) {
                            // already closing
                        }
                    }
                });
            } catch (IOException | java.util.concurrent.RejectedExecutionException e) {
                if (!closed) LOG.warn("accept failed: {}", e.getMessage());
            }
        }
    }

    /** Answers a connection over the limit with one error reply and closes it. */
    private void refuse(Socket s) {
        LOG.warn("refusing a connection from {}: {} connections open (limit {})", s.getRemoteSocketAddress(), clients.size(),
                MAX_CONNECTIONS);
        try (s) {
            s.setSoTimeout(100);
            s.getOutputStream().write((org.robopro.comms.protocol.Reply.error(0, ErrorCode.TOO_MANY_CONNECTIONS,
                    "the controller serves at most " + MAX_CONNECTIONS + " connections; close one and connect again") + "\n")
                    .getBytes(StandardCharsets.ISO_8859_1));
        } catch (IOException ignored) {
            // the refused client left already
        }
    }

    private void serveMotion(Socket s) throws IOException {
        InputStream in = s.getInputStream();
        OutputStream out = s.getOutputStream();
        ProtocolHandler.Session session = handler.newSession();
        boolean[] checksums = {false};
        StringBuilder pending = new StringBuilder();
        byte[] buf = new byte[8192];
        while (!closed) {
            int n = in.read(buf);
            if (n < 0) return;
            pending.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            int hash;
            while ((hash = pending.indexOf("#")) >= 0) {
                String request = pending.substring(0, hash + 1);
                pending.delete(0, hash + 1);
                if (!serveFaulty(s, out, session, request, checksums)) return;
            }
            if (pending.length() > OpenAbb.MAX_REQUEST_CHARS) {
                // No '#' in sight: answer once and drop the garbage rather than buffer forever.
                String reply = handler.handle(session, pending.substring(0, 64) + "...");
                pending.setLength(0);
                send(out, checksums[0] ? LinkChecksum.seal(reply, "") : reply);
            }
        }
    }

    /** Applies the request-side faults, then serves; false when the connection must end. */
    private boolean serveFaulty(Socket s, OutputStream out, ProtocolHandler.Session session, String request,
                                boolean[] checksums) throws IOException {
        switch (requestFaults.next()) {
            case DROP -> { return true; }
            case CORRUPT -> {
                return serveOne(s, out, session, new String(requestFaults.corrupt(request.getBytes(StandardCharsets.ISO_8859_1)),
                        StandardCharsets.ISO_8859_1), checksums);
            }
            case DUPLICATE -> {
                return serveOne(s, out, session, request, checksums) && serveOne(s, out, session, request, checksums);
            }
            case DELAY -> { pause(requestFaults.delayMs()); return serveOne(s, out, session, request, checksums); }
            case DISCONNECT -> { s.close(); return false; }
            default -> { return serveOne(s, out, session, request, checksums); }
        }
    }

    /**
     * Serves one request; false when the connection must end. In checksum mode (robopro protocol,
     * switched on per connection by "40 crc #") a request must carry its CRC-32 and every reply
     * carries one (see {@link LinkChecksum}); a damaged request is answered E103 and not executed.
     */
    private boolean serveOne(Socket s, OutputStream out, ProtocolHandler.Session session, String request,
                             boolean[] checksums) throws IOException {
        requests.incrementAndGet();
        if (request.strip().startsWith(Integer.toString(OpenAbb.DOWNLOAD_CHUNK) + " ") && cutAfterChunks.get() > 0
                && cutAfterChunks.decrementAndGet() == 0) {
            LOG.info("fault injection: cutting the connection in the middle of a program download");
            s.close();
            return false;
        }
        String reply;
        String key = "";
        if (LinkChecksum.isHello(request)) {
            reply = handler.handle(session, OpenAbb.request(OpenAbb.HELLO)) + " " + LinkChecksum.MODE;
            checksums[0] = true;
        } else if (checksums[0]) {
            String plain = LinkChecksum.open(request);
            key = plain == null ? "" : LinkChecksum.key(request);
            reply = plain == null ? org.robopro.comms.protocol.Reply.error(LinkChecksum.instruction(request), ErrorCode.LINK_CHECKSUM,
                    "request failed its checksum, not executed; send it again") : handler.handle(session, plain);
        } else {
            reply = handler.handle(session, request);
        }
        if (session.closeRequested()) {
            s.close(); // SERVER.mod's instruction 99: close without a reply, serve the next client
            return false;
        }
        if (checksums[0]) reply = LinkChecksum.seal(reply, key);
        switch (faults.next()) {
            case DROP -> { return true; }
            case CORRUPT -> out.write(faults.corrupt((reply + "\n").getBytes(StandardCharsets.ISO_8859_1)));
            case DUPLICATE -> { send(out, reply); send(out, reply); }
            case DELAY -> { pause(faults.delayMs()); send(out, reply); }
            case DISCONNECT -> { s.close(); return false; } // executed, but the reply never arrives
            case NONE -> send(out, reply);
        }
        out.flush();
        return true;
    }

    private static void send(OutputStream out, String reply) throws IOException {
        out.write((reply + "\n").getBytes(StandardCharsets.ISO_8859_1));
        out.flush();
    }

    private static void pause(int ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void serveLogger(Socket s) throws IOException {
        OutputStream out = s.getOutputStream();
        LocalDateTime start = LocalDateTime.now();
        String date = start.format(DateTimeFormatter.ISO_LOCAL_DATE);
        String time = start.format(DateTimeFormatter.ofPattern("HH:mm:ss"));
        SimulatedController c = handler.controller();
        try {
            while (!closed) {
                String clock = OpenAbb.num((System.nanoTime() - startNanos) * 1e-9, 2);
                Pose p = c.readPose();
                double[] q = p.quaternion();
                String cart = "# 0 " + date + " " + time + " " + clock + " " + OpenAbb.num(Units.mToMm(p.x()), 1) + " "
                        + OpenAbb.num(Units.mToMm(p.y()), 1) + " " + OpenAbb.num(Units.mToMm(p.z()), 1) + " "
                        + OpenAbb.num(q[0], 3) + " " + OpenAbb.num(q[1], 3) + " " + OpenAbb.num(q[2], 3) + " " + OpenAbb.num(q[3], 3);
                send(out, cart);
                Thread.sleep(100);
                double[] j = c.readJoints();
                StringBuilder sb = new StringBuilder("# 1 " + date + " " + time + " " + clock);
                for (double v : j) sb.append(' ').append(OpenAbb.num(Units.radToDeg(v), 2));
                send(out, sb.toString());
                Thread.sleep(100);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (SocketException e) {
            LOG.debug("logger client left: {}", e.getMessage());
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            motion.close();
            logger.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        dropClients();
        connections.shutdownNow();
    }
}
