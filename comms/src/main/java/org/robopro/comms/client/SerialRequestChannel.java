package org.robopro.comms.client;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.robopro.comms.CommsException;
import org.robopro.comms.link.ByteLink;
import org.robopro.comms.link.FaultInjector;
import org.robopro.comms.link.FramedLink;
import org.robopro.comms.link.SerialPortByteLink;

/**
 * The open_abb protocol over the framed serial link. Each message carries an exchange id
 * ("xid request" / "xid reply"), so a late reply to an earlier, timed-out request is recognised
 * and dropped instead of being taken for the current one.
 */
public final class SerialRequestChannel implements RequestChannel {

    /** Opens a {@link ByteLink}; called again on reconnect. */
    @FunctionalInterface
    public interface Opener {
        ByteLink open() throws IOException;
    }

    private final Opener opener;
    private final String description;
    private final FramedLink.Options options;
    private final FaultInjector faults;
    private FramedLink link;
    private long xid = System.nanoTime() & 0xFFFFFFFFL;

    public SerialRequestChannel(Opener opener, String description, FramedLink.Options options, FaultInjector faults) {
        this.opener = opener;
        this.description = description;
        this.options = options;
        this.faults = faults;
    }

    /** A serial device by path (e.g. /dev/ttyS0, or a pty made by socat), 8N1 at {@code baud}. */
    public static SerialRequestChannel open(String device, int baud) {
        return new SerialRequestChannel(() -> new SerialPortByteLink(device, baud), "serial " + device,
                FramedLink.Options.forBaud(baud), null);
    }

    /** The link in use (opened on demand), e.g. for its statistics. */
    public FramedLink link() {
        if (link == null || !link.isOpen()) {
            if (link != null) link.close();
            try {
                link = new FramedLink(opener.open(), options, faults);
            } catch (IOException e) {
                throw new CommsException.LinkDown("cannot open " + description + ": " + e.getMessage(), e);
            }
        }
        return link;
    }

    @Override
    public String exchange(String request, int instruction, Duration timeout) {
        FramedLink l = link();
        long id = ++xid;
        String prefix = id + " ";
        l.send((prefix + request).getBytes(StandardCharsets.ISO_8859_1));
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            long left = deadline - System.nanoTime();
            if (left <= 0)
                throw new CommsException.Timeout("controller on " + description + " did not answer '" + clip(request) + "' within "
                        + timeout.toMillis() + " ms");
            byte[] m = l.receive(Duration.ofNanos(left));
            if (m == null) continue;
            String text = new String(m, StandardCharsets.ISO_8859_1);
            if (text.startsWith(prefix)) return text.substring(prefix.length());
            // a reply to an earlier request that timed out: drop it
        }
    }

    private static String clip(String s) {
        String t = s.strip();
        return t.length() > 48 ? t.substring(0, 48) + "..." : t;
    }

    @Override
    public void reconnect() {
        if (link != null && !link.isOpen()) {
            link.close();
            link = null;
        }
        link().clearReceived();
    }

    @Override public String describe() { return description; }

    @Override
    public void close() {
        if (link != null) link.close();
        link = null;
    }
}
