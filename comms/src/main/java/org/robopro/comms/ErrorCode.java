package org.robopro.comms;

import java.util.Optional;

/**
 * Error codes the simulated controller puts after {@code ok = 0} in a reply
 * ("{@code 2 0 E110 joint 2 target 120.00 deg outside -100.00 .. 100.00}"). SERVER.mod itself
 * only sends {@code ok = 0} with no code; the client then reports {@link #BAD_MESSAGE}.
 * Documented in docs/controller-link.md.
 */
public enum ErrorCode {
    BAD_MESSAGE(100, "malformed request or wrong number of parameters"),
    UNKNOWN_INSTRUCTION(101, "unknown instruction number"),
    BAD_VALUE(102, "parameter not finite or out of range"),
    /** robopro protocol, checksum mode on TCP: the request arrived damaged and was not executed; send it again. */
    LINK_CHECKSUM(103, "request failed its link checksum (not executed)"),
    JOINT_LIMIT(110, "target outside the joint limits"),
    UNREACHABLE(111, "cartesian target not reachable"),
    PATH_UNREACHABLE(112, "linear path leaves the workspace or the joint limits"),
    BUSY(120, "a program is running"),
    NO_SUCH_PROGRAM(200, "no such program"),
    CHECKSUM_MISMATCH(201, "program length or checksum mismatch"),
    TRANSFER_STATE(202, "transfer chunk out of order or no transfer open"),
    BAD_PROGRAM_NAME(203, "bad program name"),
    PROGRAM_TOO_LARGE(204, "program too large"),
    PROGRAM_SYNTAX(205, "program does not parse"),
    PROGRAM_NOT_SIMULATED(206, "program cannot be simulated"),
    PROGRAM_RUNTIME(210, "program stopped with an error"),
    STORAGE_FULL(207, "program storage full (count or bytes)"),
    TOO_MANY_CONNECTIONS(121, "too many connections"),
    INTERNAL(300, "internal controller error");

    private final int number;
    private final String meaning;

    ErrorCode(int number, String meaning) {
        this.number = number;
        this.meaning = meaning;
    }

    public int number() { return number; }

    public String meaning() { return meaning; }

    /** Wire form, e.g. {@code E110}. */
    public String wire() { return "E" + number; }

    public static Optional<ErrorCode> fromWire(String token) {
        if (token == null || token.length() < 2 || token.charAt(0) != 'E') return Optional.empty();
        for (ErrorCode c : values()) if (c.wire().equals(token)) return Optional.of(c);
        return Optional.empty();
    }

    @Override
    public String toString() { return wire() + " (" + meaning + ")"; }
}
