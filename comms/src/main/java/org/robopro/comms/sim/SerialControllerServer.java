package org.robopro.comms.sim;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import org.robopro.comms.CommsException;
import org.robopro.comms.link.ByteLink;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.link.FramedLink;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated controller on a serial line: framed link ({@link FramedLink}), messages
 * "xid request" answered with "xid reply". When the peer starts a new link session (it
 * restarted or gave up on a message), any open program download is discarded, as on a dropped
 * TCP connection.
 */
public final class SerialControllerServer implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(SerialControllerServer.class);

    private final ProtocolHandler handler;
    private final org.robopro.comms.client.SerialRequestChannel.Opener opener;
    private final FramedLink.Options options;
    private final FaultInjector faults;
    private volatile FramedLink link;
    private final Thread worker;
    private final AtomicInteger served = new AtomicInteger();
    private volatile ProtocolHandler.Session session;
    private volatile boolean closed;

    /** Serves on the line {@code opener} opens; re-opens it (every 200 ms) when it is lost, until closed. */
    public SerialControllerServer(ProtocolHandler handler, org.robopro.comms.client.SerialRequestChannel.Opener opener,
                                  FramedLink.Options options, FaultInjector faults) throws java.io.IOException {
        this.handler = handler;
        this.opener = opener;
        this.options = options;
        this.faults = faults;
        this.session = handler.newSession();
        this.link = openLink(opener.open());
        this.worker = new Thread(this::serve, "robopro-sim-serial");
        worker.setDaemon(true);
        worker.start();
    }

    public SerialControllerServer(ProtocolHandler handler, ByteLink io, FramedLink.Options options, FaultInjector faults)
            throws java.io.IOException {
        this(handler, once(io), options, faults);
    }

    private static org.robopro.comms.client.SerialRequestChannel.Opener once(ByteLink io) {
        java.util.concurrent.atomic.AtomicBoolean used = new java.util.concurrent.atomic.AtomicBoolean();
        return () -> {
            if (used.getAndSet(true)) throw new java.io.IOException(io.describe() + " cannot be re-opened");
            return io;
        };
    }

    private FramedLink openLink(ByteLink io) {
        FramedLink l = new FramedLink(io, options, faults);
        l.onPeerReset(s -> session = handler.newSession());
        return l;
    }

    public FramedLink link() { return link; }

    public int served() { return served.get(); }

    private void serve() {
        while (!closed) {
            byte[] m;
            try {
                m = link.receive(Duration.ofMillis(200));
            } catch (CommsException.LinkDown e) {
                if (closed) return;
                LOG.warn("serial link down ({}); re-opening", e.getMessage());
                link.close();
                session = handler.newSession(); // a dropped line ends any open transfer
                if (!reopen()) return;
                continue;
            }
            if (m == null) continue;
            String text = new String(m, StandardCharsets.ISO_8859_1);
            int sp = text.indexOf(' ');
            String xid = sp > 0 ? text.substring(0, sp) : "0";
            String reply = handler.handle(session, sp > 0 ? text.substring(sp + 1) : text);
            served.incrementAndGet();
            if (reply == null) {
                session = handler.newSession();
                continue;
            }
            try {
                link.send((xid + " " + reply).getBytes(StandardCharsets.ISO_8859_1));
            } catch (CommsException.LinkDown e) {
                // The client will ask again (same request id for motions: answered from the de-duplication cache).
                LOG.info("reply not acknowledged: {}", e.getMessage());
            }
        }
    }

    private boolean reopen() {
        while (!closed) {
            try {
                Thread.sleep(200);
                link = openLink(opener.open());
                LOG.info("serial line {} re-opened", link.describe());
                return true;
            } catch (java.io.IOException e) {
                LOG.debug("re-open failed: {}", e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return false;
    }

    @Override
    public void close() {
        closed = true;
        link.close();
        try {
            worker.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
