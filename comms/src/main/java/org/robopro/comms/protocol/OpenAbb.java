package org.robopro.comms.protocol;

import java.util.Locale;

/**
 * Instruction numbers and number formats of the open_abb protocol (robotics/open_abb,
 * RAPID/SERVER.mod and abb_node/packages/abb_communications/abb.py), and robopro's extension.
 *
 * <p>Requests are "{@code NN p1 p2 ... #}": the instruction number, parameters separated by
 * single spaces, a '#' after the last space. Replies are "{@code NN ok data}" with ok 1
 * (SERVER_OK) or 0 (SERVER_BAD_MSG); SERVER.mod sends no terminator, robopro's simulator ends
 * each reply with '\n' (abb.py's {@code float()} ignores it). Lengths in mm, angles in degrees,
 * quaternions (q1..q4) with q1 the scalar. See docs/controller-link.md.
 */
public final class OpenAbb {
    private OpenAbb() { }

    // --- SERVER.mod ---
    public static final int PING = 0;
    public static final int MOVE_CARTESIAN = 1;
    public static final int MOVE_JOINTS = 2;
    public static final int GET_CARTESIAN = 3;
    public static final int GET_JOINTS = 4;
    public static final int GET_EXTERNAL_AXES = 5;
    public static final int SET_TOOL = 6;
    public static final int SET_WOBJ = 7;
    public static final int SET_SPEED = 8;
    public static final int SET_ZONE = 9;
    public static final int BUFFER_ADD = 30;
    public static final int BUFFER_CLEAR = 31;
    public static final int BUFFER_SIZE = 32;
    public static final int BUFFER_EXECUTE = 33;
    public static final int EXTERNAL_AXES_MOVE = 34;
    public static final int CIRCULAR_POINT = 35;
    public static final int CIRCULAR_MOVE = 36;
    public static final int ROBOT_INFO = 98;
    public static final int CLOSE = 99;

    // --- robopro extension (numbers SERVER.mod does not use; it answers them with ok 0) ---
    public static final int HELLO = 40;
    public static final int MOVE_CARTESIAN_TAGGED = 41;
    public static final int MOVE_JOINTS_TAGGED = 42;
    public static final int STATUS = 43;
    public static final int LIST_PROGRAMS = 44;
    public static final int DOWNLOAD_BEGIN = 45;
    public static final int DOWNLOAD_CHUNK = 46;
    public static final int DOWNLOAD_COMMIT = 47;
    public static final int UPLOAD_BEGIN = 48;
    public static final int UPLOAD_CHUNK = 49;
    public static final int RUN_PROGRAM = 50;
    public static final int STOP_PROGRAM = 51;
    public static final int MEASURE = 52;

    public static final int SERVER_OK = 1;
    public static final int SERVER_BAD_MSG = 0;

    /** Bytes of program text per chunk (before base64), so a chunk fits a serial frame. */
    public static final int CHUNK_BYTES = 480;
    /** Largest program the simulator stores. */
    public static final int MAX_PROGRAM_BYTES = 4 * 1024 * 1024;
    /** Longest request line the simulator accepts. */
    public static final int MAX_REQUEST_CHARS = 4096;

    /** Fixed-point number, '.' as separator, no grouping, "-0.00" printed as "0.00". */
    public static String num(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        if (s.startsWith("-") && Double.parseDouble(s) == 0) s = s.substring(1);
        return s;
    }

    /** A request "NN p1 ... #". */
    public static String request(int code, String... params) {
        StringBuilder sb = new StringBuilder(code < 10 ? "0" : "").append(code).append(' ');
        for (String p : params) sb.append(p).append(' ');
        return sb.append('#').toString();
    }

    /** Program names: RAPID identifiers, 1 to 32 characters. */
    public static boolean validProgramName(String name) {
        return name != null && name.matches("[A-Za-z][A-Za-z0-9_]{0,31}");
    }
}
