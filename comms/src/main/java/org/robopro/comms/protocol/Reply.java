package org.robopro.comms.protocol;

import java.util.Arrays;
import java.util.List;
import org.robopro.comms.CommsException;
import org.robopro.comms.ErrorCode;

/**
 * A parsed reply "NN ok data": instruction number, ok flag, data tokens. On ok 0 the robopro
 * simulator adds "E&lt;code&gt; message"; SERVER.mod adds nothing.
 */
public record Reply(int code, boolean ok, List<String> data, String text) {
    public Reply {
        data = List.copyOf(data);
    }

    /** Parses a reply; a malformed one is a {@link CommsException.Protocol} naming the text. */
    public static Reply parse(String text) {
        String t = text.strip();
        String[] tok = t.isEmpty() ? new String[0] : t.split("\\s+");
        if (tok.length < 2) throw new CommsException.Protocol("malformed reply '" + Request.clip(t) + "': needs 'NN ok ...'");
        int code;
        int ok;
        try {
            code = Integer.parseInt(tok[0]);
            ok = Integer.parseInt(tok[1]);
        } catch (NumberFormatException e) {
            throw new CommsException.Protocol("malformed reply '" + Request.clip(t) + "': instruction number and ok flag must be integers");
        }
        if (ok != 0 && ok != 1) throw new CommsException.Protocol("malformed reply '" + Request.clip(t) + "': ok flag " + ok + " is not 0 or 1");
        return new Reply(code, ok == 1, Arrays.asList(tok).subList(2, tok.length), t);
    }

    /** Throws {@link CommsException.Refused} if this reply says the request failed. */
    public Reply requireOk(String what) {
        if (ok) return this;
        if (!data.isEmpty()) {
            var ec = ErrorCode.fromWire(data.get(0));
            if (ec.isPresent()) {
                String msg = String.join(" ", data.subList(1, data.size()));
                throw new CommsException.Refused(ec.get(), what + ": " + msg);
            }
        }
        throw new CommsException.Refused(ErrorCode.BAD_MESSAGE, what + ": controller answered ok=0 (SERVER_BAD_MSG)"
                + (data.isEmpty() ? "" : " " + String.join(" ", data)));
    }

    /** Data token i as a finite number. */
    public double number(int i, String field) {
        if (i >= data.size()) throw new CommsException.Protocol("reply '" + Request.clip(text) + "' lacks " + field + " (data item " + (i + 1) + ")");
        try {
            double v = Double.parseDouble(data.get(i));
            if (!Double.isFinite(v)) throw new NumberFormatException();
            return v;
        } catch (NumberFormatException e) {
            throw new CommsException.Protocol("reply '" + Request.clip(text) + "': " + field + " '" + Request.clip(data.get(i)) + "' is not a finite number");
        }
    }

    public long natural(int i, String field) {
        if (i >= data.size()) throw new CommsException.Protocol("reply '" + Request.clip(text) + "' lacks " + field + " (data item " + (i + 1) + ")");
        try {
            long v = Long.parseLong(data.get(i));
            if (v < 0) throw new NumberFormatException();
            return v;
        } catch (NumberFormatException e) {
            throw new CommsException.Protocol("reply '" + Request.clip(text) + "': " + field + " '" + Request.clip(data.get(i)) + "' is not a non-negative integer");
        }
    }

    public String token(int i, String field) {
        if (i >= data.size()) throw new CommsException.Protocol("reply '" + Request.clip(text) + "' lacks " + field + " (data item " + (i + 1) + ")");
        return data.get(i);
    }

    public void expectAtLeast(int n, String what) {
        if (data.size() < n) throw new CommsException.Protocol("reply to " + what + " '" + Request.clip(text) + "' has " + data.size() + " data items, expected " + n);
    }

    /** The reply text for a refused request, as the simulator sends it. */
    public static String error(int code, ErrorCode error, String message) {
        return code + " 0 " + error.wire() + " " + message.replace('\n', ' ').replace('#', ' ');
    }
}
