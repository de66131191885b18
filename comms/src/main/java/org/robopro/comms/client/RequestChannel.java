package org.robopro.comms.client;

import java.time.Duration;

/**
 * Carries one protocol request and brings back its reply: TCP ({@link TcpRequestChannel}) or
 * the framed serial link ({@link SerialRequestChannel}). Not thread-safe; one caller at a time.
 */
public interface RequestChannel extends AutoCloseable {

    /**
     * Sends {@code request} ("NN ... #") and returns the reply text for instruction
     * {@code instruction}. Throws {@link org.robopro.comms.CommsException.Timeout} when no reply
     * comes within {@code timeout}, {@link org.robopro.comms.CommsException.LinkDown} when the
     * link fails.
     */
    String exchange(String request, int instruction, Duration timeout);

    /** Drops and re-opens the link. */
    void reconnect();

    /** "tcp 127.0.0.1:5000", "serial /dev/ttyS0", for messages. */
    String describe();

    @Override
    void close();
}
