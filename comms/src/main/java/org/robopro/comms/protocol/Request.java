package org.robopro.comms.protocol;

import java.util.ArrayList;
import java.util.List;
import org.robopro.comms.ErrorCode;

/**
 * A parsed request "NN p1 ... #" (SERVER.mod's ParseMsg: text up to the first '#', split at
 * spaces, the first token the instruction number). Parameters stay text; the handler converts
 * them, so a bad one can be named in the error reply.
 */
public record Request(int code, List<String> params, String text) {
    public Request {
        params = List.copyOf(params);
    }

    /** Parses a request; throws {@link RequestException} with the code to put in the reply. */
    public static Request parse(String text) {
        if (text.length() > OpenAbb.MAX_REQUEST_CHARS)
            throw new RequestException(-1, ErrorCode.BAD_MESSAGE, "request longer than " + OpenAbb.MAX_REQUEST_CHARS + " characters");
        int end = text.indexOf('#');
        if (end < 0) throw new RequestException(-1, ErrorCode.BAD_MESSAGE, "no '#' at the end of the request");
        String body = text.substring(0, end).strip();
        if (body.isEmpty()) throw new RequestException(-1, ErrorCode.BAD_MESSAGE, "empty request");
        String[] tokens = body.split("\\s+");
        int code;
        try {
            code = Integer.parseInt(tokens[0]);
        } catch (NumberFormatException e) {
            throw new RequestException(-1, ErrorCode.BAD_MESSAGE, "instruction number '" + clip(tokens[0]) + "' is not an integer");
        }
        if (code < 0 || code > 999) throw new RequestException(-1, ErrorCode.BAD_MESSAGE, "instruction number " + code + " out of range");
        List<String> p = new ArrayList<>(tokens.length - 1);
        for (int i = 1; i < tokens.length; i++) p.add(tokens[i]);
        return new Request(code, p, text);
    }

    public int count() { return params.size(); }

    /** Parameter i (0-based) as a finite number. */
    public double number(int i, String field) {
        String s = params.get(i);
        try {
            double v = Double.parseDouble(s);
            if (!Double.isFinite(v)) throw new NumberFormatException();
            // Java accepts "1e3", "0x1p3", "NaN", "1d": allow only plain decimal numbers on the wire.
            if (!s.matches("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?")) throw new NumberFormatException();
            return v;
        } catch (NumberFormatException e) {
            throw new RequestException(code, ErrorCode.BAD_VALUE, field + " (parameter " + (i + 1) + ") '" + clip(s) + "' is not a finite number");
        }
    }

    /** Parameter i as a non-negative long (request ids, offsets, lengths). */
    public long natural(int i, String field) {
        String s = params.get(i);
        try {
            long v = Long.parseLong(s);
            if (v < 0) throw new NumberFormatException();
            return v;
        } catch (NumberFormatException e) {
            throw new RequestException(code, ErrorCode.BAD_VALUE, field + " (parameter " + (i + 1) + ") '" + clip(s) + "' is not a non-negative integer");
        }
    }

    public void expectCount(int... allowed) {
        for (int a : allowed) if (params.size() == a) return;
        StringBuilder sb = new StringBuilder();
        for (int a : allowed) sb.append(sb.length() == 0 ? "" : " or ").append(a);
        throw new RequestException(code, ErrorCode.BAD_MESSAGE, "instruction " + code + " takes " + sb + " parameters, got " + params.size());
    }

    public static String clip(String s) { return s.length() > 40 ? s.substring(0, 40) + "..." : s; }

    /** A request the controller refuses: the reply carries {@code code} and the message. */
    public static final class RequestException extends RuntimeException {
        private static final long serialVersionUID = 1L;
        private final int instruction;
        private final ErrorCode error;

        public RequestException(int instruction, ErrorCode error, String message) {
            super(message);
            this.instruction = instruction;
            this.error = error;
        }

        /** The instruction number, or -1 when the request was too malformed to read it. */
        public int instruction() { return instruction; }

        public ErrorCode error() { return error; }
    }
}
