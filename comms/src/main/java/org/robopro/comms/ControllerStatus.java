package org.robopro.comms;

/**
 * The controller's state: {@code IDLE}, {@code RUNNING} a program, or {@code ERROR} (the last
 * program stopped on an error); the running or last program's name (empty if none); how many
 * errors were logged; the last error (null if none); the controller clock in seconds.
 */
public record ControllerStatus(State state, String program, int errorCount, ErrorCode lastError,
                               String lastErrorMessage, double clockS) {
    public enum State { IDLE, RUNNING, ERROR }
}
