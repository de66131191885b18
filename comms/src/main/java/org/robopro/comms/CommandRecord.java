package org.robopro.comms;

import java.time.Instant;

/**
 * One step in a command's life, as the invoker logs it and tells listeners: queued, running,
 * retrying (with the cause), then succeeded, failed or cancelled.
 *
 * @param requestId the command's request id
 * @param description the command with its arguments
 * @param state       this step
 * @param attempt     1 for the first sending, 2 for the first retry, ...
 * @param time        when the step happened
 * @param detail      the result, or the error message, or empty
 */
public record CommandRecord(long requestId, String description, State state, int attempt, Instant time,
                            String detail) {
    public enum State {
        QUEUED, RUNNING, RETRYING, SUCCEEDED, FAILED, CANCELLED;

        public boolean isFinal() { return this == SUCCEEDED || this == FAILED || this == CANCELLED; }
    }

    @Override
    public String toString() {
        return time + " " + state + " " + description + (attempt > 1 ? " (attempt " + attempt + ")" : "")
                + (detail.isEmpty() ? "" : ": " + detail);
    }
}
