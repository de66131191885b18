package org.robopro.comms;

import java.security.SecureRandom;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A Command of the seed paper's Command pattern (§2.1, Fig. 3): one request to the controller,
 * executed by a {@link CommandInvoker} against a {@link ControllerReceiver}.
 *
 * <p>Each command gets a request id when it is made and keeps it across retries, so a
 * controller that de-duplicates ids never executes a motion twice even if a reply is lost and
 * the invoker sends the command again.
 *
 * @param <T> the result type ({@link Void} for commands without a result)
 */
public abstract class ControllerCommand<T> {

    /** When the invoker may send a command again after a timeout or a dropped link. */
    public enum RetryPolicy {
        /** Reads and settings: executing twice is harmless. */
        SAFE,
        /** Motions and program starts: only when the receiver de-duplicates request ids. */
        IF_DEDUPLICATED,
        /** Never re-sent. */
        NEVER
    }

    // Random start so ids from two client processes (or a restarted client) do not collide in
    // the controller's de-duplication window.
    private static final AtomicLong NEXT_ID =
            new AtomicLong((new SecureRandom().nextLong() >>> 24) * 1000 + 1);

    private final String name;
    private final RetryPolicy retryPolicy;
    private final long requestId;

    protected ControllerCommand(String name, RetryPolicy retryPolicy) {
        this.name = name;
        this.retryPolicy = retryPolicy;
        this.requestId = NEXT_ID.getAndIncrement();
    }

    /** Runs the command against the receiver; throws {@link CommsException} on failure. */
    public abstract T execute(ControllerReceiver receiver);

    /** Short name, e.g. {@code move-joints}. */
    public String name() { return name; }

    public RetryPolicy retryPolicy() { return retryPolicy; }

    public long requestId() { return requestId; }

    /** Whether it is safe to send this command again to {@code receiver}. */
    public boolean mayRetry(ControllerReceiver receiver) {
        return switch (retryPolicy) {
            case SAFE -> true;
            case IF_DEDUPLICATED -> receiver.deduplicatesRequests();
            case NEVER -> false;
        };
    }

    /** Arguments for logs and the GUI, in the units the user sees (mm, deg). */
    protected String arguments() { return ""; }

    /** Name, request id and arguments, for the history and the GUI. */
    public String describe() {
        String a = arguments();
        return name + " #" + requestId + (a.isEmpty() ? "" : " " + a);
    }

    @Override
    public String toString() { return describe(); }
}
