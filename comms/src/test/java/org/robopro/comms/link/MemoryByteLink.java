package org.robopro.comms.link;

import java.io.IOException;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** An in-memory byte pipe pair, for link-layer tests without a serial port. */
public final class MemoryByteLink implements ByteLink {
    private static final byte[] EOF = new byte[0];
    private final BlockingQueue<byte[]> in;
    private final BlockingQueue<byte[]> out;
    private final String name;
    private volatile boolean closed;
    private byte[] pending;
    private int pendingOff;

    private MemoryByteLink(BlockingQueue<byte[]> in, BlockingQueue<byte[]> out, String name) {
        this.in = in;
        this.out = out;
        this.name = name;
    }

    /** Two ends connected to each other. */
    public static MemoryByteLink[] pair() {
        BlockingQueue<byte[]> ab = new LinkedBlockingQueue<>(), ba = new LinkedBlockingQueue<>();
        return new MemoryByteLink[] {new MemoryByteLink(ba, ab, "memory A"), new MemoryByteLink(ab, ba, "memory B")};
    }

    @Override
    public int read(byte[] buf) throws IOException {
        if (closed) return -1;
        try {
            if (pending == null) {
                pending = in.poll(50, TimeUnit.MILLISECONDS);
                pendingOff = 0;
                if (pending == null) return 0;
                if (pending == EOF) {
                    closed = true;
                    return -1;
                }
            }
            int n = Math.min(buf.length, pending.length - pendingOff);
            System.arraycopy(pending, pendingOff, buf, 0, n);
            pendingOff += n;
            if (pendingOff == pending.length) pending = null;
            return n;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted");
        }
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        if (closed) throw new IOException(name + " closed");
        out.add(bytes.clone());
    }

    @Override public String describe() { return name; }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            out.add(EOF);
        }
    }
}
