package org.robopro.comms;

/**
 * A command could not be completed. Subclasses say why: the controller refused it, the link
 * went down, the controller did not answer in time, or a reply was malformed. All are
 * unchecked so that {@link ControllerReceiver} reads like a plain API; the invoker maps them to
 * failed futures.
 */
public class CommsException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public CommsException(String message) { super(message); }

    public CommsException(String message, Throwable cause) { super(message, cause); }

    /** The controller answered and refused the request (out of limits, unreachable, bad program, ...). */
    public static final class Refused extends CommsException {
        private static final long serialVersionUID = 1L;
        private final ErrorCode code;

        public Refused(ErrorCode code, String message) {
            super(code + " " + message);
            this.code = code;
        }

        public ErrorCode code() { return code; }
    }

    /** The controller did not answer within the timeout. Whether the request executed is unknown. */
    public static final class Timeout extends CommsException {
        private static final long serialVersionUID = 1L;

        public Timeout(String message) { super(message); }
    }

    /** The link (socket, serial port) is down or broke while the request was on its way. */
    public static final class LinkDown extends CommsException {
        private static final long serialVersionUID = 1L;

        public LinkDown(String message, Throwable cause) { super(message, cause); }

        public LinkDown(String message) { super(message); }
    }

    /** A reply (or request, on the controller side) does not follow the protocol. */
    public static final class Protocol extends CommsException {
        private static final long serialVersionUID = 1L;

        public Protocol(String message) { super(message); }
    }
}
