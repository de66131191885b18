package org.robopro.comms.link;

import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Seeded fault injection for a link: each frame (or reply) is dropped, corrupted, duplicated
 * or delayed with the given probabilities. Counts what it did, so tests can print it.
 * Thread-safe.
 */
public final class FaultInjector {
    public enum Fault { NONE, DROP, CORRUPT, DUPLICATE, DELAY, DISCONNECT }

    private final Random random;
    private final double drop, corrupt, duplicate, delay, disconnect;
    private final int maxDelayMs;
    private final AtomicLong[] counts = new AtomicLong[Fault.values().length];

    public FaultInjector(long seed, double drop, double corrupt, double duplicate, double delay, int maxDelayMs) {
        this(seed, drop, corrupt, duplicate, delay, 0, maxDelayMs);
    }

    /** With {@code disconnect}: the probability that the connection is cut instead (transports that have one). */
    public FaultInjector(long seed, double drop, double corrupt, double duplicate, double delay, double disconnect, int maxDelayMs) {
        if (drop < 0 || corrupt < 0 || duplicate < 0 || delay < 0 || disconnect < 0
                || drop + corrupt + duplicate + delay + disconnect > 1 || maxDelayMs < 0)
            throw new IllegalArgumentException("bad fault rates " + drop + ", " + corrupt + ", " + duplicate + ", " + delay);
        this.random = new Random(seed);
        this.drop = drop;
        this.corrupt = corrupt;
        this.duplicate = duplicate;
        this.delay = delay;
        this.disconnect = disconnect;
        this.maxDelayMs = maxDelayMs;
        for (int i = 0; i < counts.length; i++) counts[i] = new AtomicLong();
    }

    /** {@code totalRate} split evenly over the four kinds of fault; delays up to {@code maxDelayMs}. */
    public static FaultInjector uniform(long seed, double totalRate, int maxDelayMs) {
        double r = totalRate / 4;
        return new FaultInjector(seed, r, r, r, r, maxDelayMs);
    }

    /** {@code totalRate} split evenly over the five kinds of fault, disconnects included. */
    public static FaultInjector uniformWithDisconnect(long seed, double totalRate, int maxDelayMs) {
        double r = totalRate / 5;
        return new FaultInjector(seed, r, r, r, r, r, maxDelayMs);
    }

    public static FaultInjector none() { return new FaultInjector(0, 0, 0, 0, 0, 0); }

    public synchronized Fault next() {
        double u = random.nextDouble();
        Fault f;
        if (u < drop) f = Fault.DROP;
        else if (u < drop + corrupt) f = Fault.CORRUPT;
        else if (u < drop + corrupt + duplicate) f = Fault.DUPLICATE;
        else if (u < drop + corrupt + duplicate + delay) f = Fault.DELAY;
        else if (u < drop + corrupt + duplicate + delay + disconnect) f = Fault.DISCONNECT;
        else f = Fault.NONE;
        counts[f.ordinal()].incrementAndGet();
        return f;
    }

    /** A copy of {@code bytes} with one byte changed (at a random index). */
    public synchronized byte[] corrupt(byte[] bytes) {
        byte[] c = bytes.clone();
        if (c.length > 0) {
            int i = random.nextInt(c.length);
            c[i] ^= (byte) (1 + random.nextInt(255));
        }
        return c;
    }

    public synchronized int delayMs() { return maxDelayMs == 0 ? 0 : 1 + random.nextInt(maxDelayMs); }

    public long count(Fault f) { return counts[f.ordinal()].get(); }

    public long faults() {
        return count(Fault.DROP) + count(Fault.CORRUPT) + count(Fault.DUPLICATE) + count(Fault.DELAY) + count(Fault.DISCONNECT);
    }

    @Override
    public String toString() {
        return "faults[drop " + count(Fault.DROP) + ", corrupt " + count(Fault.CORRUPT) + ", duplicate "
                + count(Fault.DUPLICATE) + ", delay " + count(Fault.DELAY)
                + (disconnect > 0 ? ", disconnect " + count(Fault.DISCONNECT) : "") + " of " + (faults() + count(Fault.NONE)) + "]";
    }
}
