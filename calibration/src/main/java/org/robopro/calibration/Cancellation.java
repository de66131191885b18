package org.robopro.calibration;

import java.util.concurrent.CancellationException;

/**
 * A cancellation token: a GUI button or Ctrl-C sets it, long computations poll it between
 * iterations and stop with a {@link CancellationException}. Thread-safe.
 */
public final class Cancellation {
    /** A token that is never cancelled. */
    public static final Cancellation NONE = new Cancellation();

    private volatile boolean cancelled;

    public void cancel() {
        if (this != NONE) cancelled = true;
    }

    public boolean isCancelled() { return cancelled; }

    /** Throws {@link CancellationException} when cancelled. */
    public void check() {
        if (cancelled) throw new CancellationException("cancelled");
    }
}
