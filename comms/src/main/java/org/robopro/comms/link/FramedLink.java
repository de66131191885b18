package org.robopro.comms.link;

import java.io.IOException;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.IntConsumer;
import org.robopro.comms.CommsException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A reliable message link over an unreliable byte line ({@link FrameCodec} frames): stop-and-wait
 * ARQ with 16-bit sequence numbers, ACK/NAK, retransmission on timeout, and duplicate
 * suppression, so each message is delivered to the peer exactly once and in order while the
 * link works. Each side numbers its messages within a random session id; a sender that gave
 * up starts a new session (seq 0), which tells the receiver to reset, so a message whose fate
 * was unknown is never taken for a duplicate.
 *
 * <p>Full duplex: a reader thread handles incoming frames (delivering DATA, matching ACKs)
 * while {@link #send} waits for its acknowledgement. Optional {@link FaultInjector} on every
 * outgoing frame.
 */
public final class FramedLink implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(FramedLink.class);
    private static final SecureRandom RANDOM = new SecureRandom();
    private static final AtomicInteger THREADS = new AtomicInteger();

    /**
     * @param ackTimeout  wait for an ACK before retransmitting
     * @param maxAttempts transmissions of one message before giving up
     */
    public record Options(Duration ackTimeout, int maxAttempts) {
        public Options {
            if (ackTimeout.isZero() || ackTimeout.isNegative() || maxAttempts < 1)
                throw new IllegalArgumentException("bad link options " + ackTimeout + ", " + maxAttempts);
        }

        /** For a line at {@code baud}: time for a maximal frame twice over, plus 20 ms. */
        public static Options forBaud(int baud) {
            long ms = 20 + 2L * (FrameCodec.MAX_PAYLOAD + 16) * 10 * 1000 / baud;
            return new Options(Duration.ofMillis(ms), 10);
        }
    }

    private final ByteLink io;
    private final Options options;
    private final FaultInjector faults;
    private final ScheduledExecutorService delayer;
    private final Thread reader;
    private final BlockingQueue<byte[]> delivered = new LinkedBlockingQueue<>();
    private final Object sendLock = new Object();
    private final Object ackLock = new Object();
    private final Object writeLock = new Object();

    private volatile boolean closed;
    private volatile IOException failure;
    private int mySession;
    private int nextSeq;
    private int outstandingSeq = -1;
    private boolean acked;
    private boolean nakked;
    private int peerSession = -1;
    private int peerLastSeq = -1;
    private volatile IntConsumer peerResetListener = s -> { };

    private final AtomicLong sent = new AtomicLong(), retransmissions = new AtomicLong(), deliveredCount = new AtomicLong(),
            duplicates = new AtomicLong(), badFrames = new AtomicLong();

    public FramedLink(ByteLink io, Options options, FaultInjector faults) {
        this.io = io;
        this.options = options;
        this.faults = faults == null ? FaultInjector.none() : faults;
        this.mySession = RANDOM.nextInt(0x10000);
        this.delayer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "robopro-link-delay-" + THREADS.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        this.reader = new Thread(this::readLoop, "robopro-link-reader-" + THREADS.incrementAndGet());
        reader.setDaemon(true);
        reader.start();
    }

    public String describe() { return io.describe(); }

    /** Called (on the reader thread) when the peer starts a new session: it restarted or gave up on a message. */
    public void onPeerReset(IntConsumer listener) { this.peerResetListener = listener; }

    /**
     * Sends one message and waits until the peer acknowledges it. Throws
     * {@link CommsException.LinkDown} when the link is closed or no acknowledgement came after
     * {@code maxAttempts} transmissions (then the next message starts a new session).
     */
    public void send(byte[] payload) {
        if (payload.length > FrameCodec.MAX_PAYLOAD)
            throw new IllegalArgumentException("message of " + payload.length + " bytes > " + FrameCodec.MAX_PAYLOAD);
        synchronized (sendLock) {
            checkOpen();
            int seq;
            int session;
            synchronized (ackLock) {
                seq = nextSeq;
                session = mySession;
                outstandingSeq = seq;
                acked = false;
                nakked = false;
            }
            byte[] frame = FrameCodec.encode(new Frame(Frame.Type.DATA, session, seq, payload));
            for (int attempt = 1; attempt <= options.maxAttempts(); attempt++) {
                if (attempt > 1) retransmissions.incrementAndGet();
                sent.incrementAndGet();
                transmit(frame);
                synchronized (ackLock) {
                    long deadline = System.nanoTime() + options.ackTimeout().toNanos();
                    while (!acked && !nakked && !closed) {
                        long left = deadline - System.nanoTime();
                        if (left <= 0) break;
                        try {
                            TimeUnit.NANOSECONDS.timedWait(ackLock, left);
                        } catch (InterruptedException e) {
                            Thread.currentThread().interrupt();
                            throw new CommsException.LinkDown("interrupted while sending on " + io.describe());
                        }
                    }
                    if (acked) {
                        outstandingSeq = -1;
                        nextSeq = (seq + 1) & 0xFFFF;
                        return;
                    }
                    nakked = false;
                }
                checkOpen();
            }
            synchronized (ackLock) {
                outstandingSeq = -1;
                mySession = (mySession + 1 + RANDOM.nextInt(0xFFFE)) & 0xFFFF;
                nextSeq = 0;
            }
            throw new CommsException.LinkDown("no acknowledgement from the peer on " + io.describe() + " after "
                    + options.maxAttempts() + " transmissions (" + options.ackTimeout().toMillis() + " ms apart)");
        }
    }

    /** The next message from the peer, or null if none came within {@code timeout}. */
    public byte[] receive(Duration timeout) {
        try {
            byte[] m = delivered.poll(timeout.toNanos(), TimeUnit.NANOSECONDS);
            if (m == null) checkOpen();
            return m;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new CommsException.LinkDown("interrupted while receiving on " + io.describe());
        }
    }

    /** Discards messages received but not yet taken. */
    public void clearReceived() { delivered.clear(); }

    private void checkOpen() {
        if (failure != null) throw new CommsException.LinkDown("link " + io.describe() + " lost: " + failure.getMessage(), failure);
        if (closed) throw new CommsException.LinkDown("link " + io.describe() + " is closed");
    }

    public boolean isOpen() { return !closed && failure == null; }

    private void transmit(byte[] frame) {
        switch (faults.next()) {
            case DROP -> { }
            case CORRUPT -> write(faults.corrupt(frame));
            case DUPLICATE -> { write(frame); write(frame); }
            case DELAY -> {
                int ms = faults.delayMs();
                try {
                    delayer.schedule(() -> write(frame), ms, TimeUnit.MILLISECONDS);
                } catch (java.util.concurrent.RejectedExecutionException e) {
                    // closing
                }
            }
            case NONE -> write(frame);
        }
    }

    private void write(byte[] bytes) {
        synchronized (writeLock) {
            try {
                io.write(bytes);
            } catch (IOException e) {
                if (!closed) {
                    failure = e;
                    LOG.warn("write to {} failed: {}", io.describe(), e.getMessage());
                }
                synchronized (ackLock) {
                    ackLock.notifyAll();
                }
            }
        }
    }

    private void readLoop() {
        FrameCodec.Decoder decoder = new FrameCodec.Decoder(this::onFrame, this::onBadFrame);
        byte[] buf = new byte[4096];
        try {
            while (!closed) {
                int n = io.read(buf);
                if (n < 0) {
                    if (!closed) failure = new IOException(io.describe() + " closed by the other side");
                    break;
                }
                decoder.feed(buf, 0, n);
            }
        } catch (IOException e) {
            if (!closed) failure = e;
        } catch (RuntimeException e) {
            LOG.error("link reader on {} failed", io.describe(), e);
            failure = new IOException(e.toString(), e);
        } finally {
            synchronized (ackLock) {
                ackLock.notifyAll();
            }
        }
    }

    private void onBadFrame(String why) {
        badFrames.incrementAndGet();
        LOG.debug("bad frame on {}: {}", io.describe(), why);
        transmit(FrameCodec.encode(new Frame(Frame.Type.NAK, 0, 0, null)));
    }

    private void onFrame(Frame f) {
        switch (f.type()) {
            case DATA -> {
                boolean deliver;
                boolean reset = false;
                synchronized (ackLock) {
                    if (f.session() != peerSession && (peerSession < 0 || f.seq() == 0)) {
                        reset = peerSession >= 0;
                        peerSession = f.session();
                        deliver = true;
                    } else if (f.session() != peerSession) {
                        deliver = false; // stale frame of an old session
                        badFrames.incrementAndGet();
                        return;
                    } else if (f.seq() == peerLastSeq) {
                        deliver = false; // duplicate: acknowledge again, do not deliver
                        duplicates.incrementAndGet();
                    } else if (f.seq() == ((peerLastSeq + 1) & 0xFFFF)) {
                        deliver = true;
                    } else {
                        badFrames.incrementAndGet(); // out of order (a delayed old copy): ignore
                        return;
                    }
                    if (deliver) peerLastSeq = f.seq();
                }
                if (reset) peerResetListener.accept(f.session());
                if (deliver) {
                    deliveredCount.incrementAndGet();
                    delivered.add(f.payload());
                }
                transmit(FrameCodec.encode(new Frame(Frame.Type.ACK, f.session(), f.seq(), null)));
            }
            case ACK -> {
                synchronized (ackLock) {
                    if (f.session() == mySession && f.seq() == outstandingSeq) {
                        acked = true;
                        ackLock.notifyAll();
                    }
                }
            }
            case NAK -> {
                synchronized (ackLock) {
                    if (outstandingSeq >= 0 && !acked) {
                        nakked = true;
                        ackLock.notifyAll();
                    }
                }
            }
        }
    }

    /** Counters: frames sent, retransmissions, messages delivered, duplicates suppressed, bad frames. */
    public String stats() {
        return "frames sent " + sent + ", retransmissions " + retransmissions + ", delivered " + deliveredCount
                + ", duplicates suppressed " + duplicates + ", bad frames " + badFrames;
    }

    public long duplicatesSuppressed() { return duplicates.get(); }

    public long retransmissions() { return retransmissions.get(); }

    @Override
    public void close() {
        closed = true;
        delayer.shutdownNow();
        io.close();
        synchronized (ackLock) {
            ackLock.notifyAll();
        }
        try {
            reader.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
