package org.robopro.comms.link;

import java.io.IOException;

/** A raw byte stream to the peer (a serial port, or an in-memory pipe in tests). */
public interface ByteLink extends AutoCloseable {

    /** Reads up to buf.length bytes; 0 when none came within the link's poll time; -1 when the link is closed or lost. */
    int read(byte[] buf) throws IOException;

    void write(byte[] bytes) throws IOException;

    String describe();

    @Override
    void close();
}
