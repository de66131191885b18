package org.robopro.comms.client;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Base64;
import java.util.List;
import java.util.Locale;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerReceiver;
import org.robopro.comms.ControllerStatus;
import org.robopro.calibration.PoseConditions;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.TrackerReading;
import org.robopro.comms.MotionResult;
import org.robopro.comms.ProgramInfo;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ZoneData;
import org.robopro.comms.protocol.Checksums;
import org.robopro.comms.protocol.OpenAbb;
import org.robopro.comms.protocol.Reply;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;

/**
 * The controller as a {@link ControllerReceiver}, over any {@link RequestChannel}, speaking the
 * open_abb protocol. On first contact it sends robopro's HELLO (40): a robopro controller
 * answers and the client then uses tagged motions (de-duplicated by request id), program
 * transfer and the tracker; a plain SERVER.mod answers ok 0, and the client sticks to the
 * standard instructions (motions are then never re-sent by the invoker).
 *
 * <p>Converts SI to mm/deg at the wire. Checks every reply: its instruction number, its
 * request id, its number count, and for program transfers the length and CRC-32 end to end.
 */
public final class ProtocolClient implements ControllerReceiver {
    private final RequestChannel channel;
    private Duration timeout = Duration.ofSeconds(5);
    private Boolean extended; // null until HELLO
    private String robotName = "";

    public ProtocolClient(RequestChannel channel) { this.channel = channel; }

    public RequestChannel channel() { return channel; }

    /** True when the controller speaks robopro's extension (known after the first request). */
    public boolean extended() {
        hello();
        return extended;
    }

    /** The robot name the controller announced (robopro controllers), else empty. */
    public String robotName() {
        hello();
        return robotName;
    }

    private void hello() {
        if (extended != null) return;
        Reply r = Reply.parse(channel.exchange(OpenAbb.request(OpenAbb.HELLO), OpenAbb.HELLO, timeout));
        checkCode(r, OpenAbb.HELLO);
        extended = r.ok() && !r.data().isEmpty() && r.data().get(0).equals("robopro");
        if (extended && r.data().size() >= 3) robotName = r.data().get(2);
    }

    private Reply call(int code, String what, String... params) {
        hello();
        String req = OpenAbb.request(code, params);
        Reply r = Reply.parse(channel.exchange(req, code, timeout));
        checkCode(r, code);
        return r.requireOk(what);
    }

    private void checkCode(Reply r, int code) {
        if (r.code() != code)
            throw new CommsException.Protocol("reply '" + clip(r.text()) + "' is for instruction " + r.code() + ", expected " + code
                    + " (" + channel.describe() + ")");
    }

    private void requireExtended(String what) {
        hello();
        if (!extended)
            throw new CommsException.Refused(ErrorCode.UNKNOWN_INSTRUCTION, what + " needs robopro's protocol extension; "
                    + channel.describe() + " speaks plain open_abb (SERVER.mod)");
    }

    private static String clip(String s) { return s.length() > 60 ? s.substring(0, 60) + "..." : s; }

    private static String mm(double m) { return OpenAbb.num(Units.mToMm(m), 3); }

    private static String deg(double rad) { return OpenAbb.num(Units.radToDeg(rad), 4); }

    private static String[] pose(Pose p) {
        double[] q = p.quaternion();
        return new String[] {mm(p.x()), mm(p.y()), mm(p.z()), OpenAbb.num(q[0], 8), OpenAbb.num(q[1], 8), OpenAbb.num(q[2], 8), OpenAbb.num(q[3], 8)};
    }

    private static String[] concat(String first, String[] rest) {
        String[] a = new String[rest.length + 1];
        a[0] = first;
        System.arraycopy(rest, 0, a, 1, rest.length);
        return a;
    }

    private static String[] joints(double[] q) {
        if (q.length != 6) throw new IllegalArgumentException("the protocol carries 6 joints, got " + q.length);
        String[] s = new String[6];
        for (int i = 0; i < 6; i++) s[i] = deg(q[i]);
        return s;
    }

    @Override public void ping() { call(OpenAbb.PING, "ping"); }

    @Override
    public double[] readJoints() {
        Reply r = call(OpenAbb.GET_JOINTS, "read joints");
        r.expectAtLeast(6, "read joints");
        double[] q = new double[6];
        for (int i = 0; i < 6; i++) q[i] = Units.degToRad(r.number(i, "joint " + (i + 1)));
        return q;
    }

    @Override
    public Pose readPose() {
        Reply r = call(OpenAbb.GET_CARTESIAN, "read pose");
        r.expectAtLeast(7, "read pose");
        double[] v = new double[7];
        String[] names = {"x", "y", "z", "q1", "q2", "q3", "q4"};
        for (int i = 0; i < 7; i++) v[i] = r.number(i, names[i]);
        try {
            return Pose.fromQuaternion(v[3], v[4], v[5], v[6], Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
        } catch (IllegalArgumentException e) {
            throw new CommsException.Protocol("reply '" + clip(r.text()) + "': " + e.getMessage());
        }
    }

    @Override
    public MotionResult moveJoints(long requestId, double[] q) {
        hello();
        if (!extended) {
            call(OpenAbb.MOVE_JOINTS, "move joints", joints(q));
            return new MotionResult(Double.NaN);
        }
        Reply r = call(OpenAbb.MOVE_JOINTS_TAGGED, "move joints", concat(Long.toString(requestId), joints(q)));
        return motionResult(r, requestId);
    }

    @Override
    public MotionResult moveLinear(long requestId, Pose wobjTtool) {
        hello();
        if (!extended) {
            call(OpenAbb.MOVE_CARTESIAN, "move linear", pose(wobjTtool));
            return new MotionResult(Double.NaN);
        }
        Reply r = call(OpenAbb.MOVE_CARTESIAN_TAGGED, "move linear", concat(Long.toString(requestId), pose(wobjTtool)));
        return motionResult(r, requestId);
    }

    private static MotionResult motionResult(Reply r, long requestId) {
        long id = r.natural(0, "request id");
        if (id != requestId) throw new CommsException.Protocol("reply '" + clip(r.text()) + "' is for request " + id + ", expected " + requestId);
        return new MotionResult(r.number(1, "motion time"));
    }

    @Override public void setTool(Pose flangeTtool) { call(OpenAbb.SET_TOOL, "set tool", pose(flangeTtool)); }

    @Override public void setWorkObject(Pose baseTwobj) { call(OpenAbb.SET_WOBJ, "set work object", pose(baseTwobj)); }

    @Override
    public void setSpeed(SpeedData s) {
        call(OpenAbb.SET_SPEED, "set speed", OpenAbb.num(Units.mToMm(s.vTcp()), 3), deg(s.vOri()),
                OpenAbb.num(Units.mToMm(s.vLeax()), 3), deg(s.vReax()));
    }

    @Override
    public void setZone(ZoneData z) {
        call(OpenAbb.SET_ZONE, "set zone", z.finep() ? "1" : "0", OpenAbb.num(Units.mToMm(z.pzoneTcp()), 4),
                OpenAbb.num(Units.mToMm(z.pzoneOri()), 4), deg(z.zoneOri()));
    }

    @Override
    public ProgramInfo downloadProgram(String name, byte[] text) {
        requireExtended("program download");
        if (!OpenAbb.validProgramName(name))
            throw new IllegalArgumentException("program name '" + name + "' is not a RAPID identifier of 1 to 32 characters");
        long crc = Checksums.crc32(text);
        call(OpenAbb.DOWNLOAD_BEGIN, "download " + name, name, Integer.toString(text.length), Checksums.hex(crc));
        for (int off = 0; off < text.length; off += OpenAbb.CHUNK_BYTES) {
            int n = Math.min(OpenAbb.CHUNK_BYTES, text.length - off);
            String b64 = Base64.getEncoder().encodeToString(Arrays.copyOfRange(text, off, off + n));
            Reply r = call(OpenAbb.DOWNLOAD_CHUNK, "download " + name, Integer.toString(off), b64);
            long next = r.natural(0, "next offset");
            if (next != off + n) throw new CommsException.Protocol("controller acknowledged offset " + next + ", expected " + (off + n));
        }
        Reply r = call(OpenAbb.DOWNLOAD_COMMIT, "download " + name);
        ProgramInfo stored = new ProgramInfo(r.token(0, "name"), (int) r.natural(1, "length"), Checksums.parseHex(r.token(2, "crc32")));
        if (!stored.name().equals(name) || stored.length() != text.length || stored.crc32() != crc)
            throw new CommsException.Protocol("controller stored " + stored + " but " + name + " has " + text.length
                    + " bytes, crc " + Checksums.hex(crc) + ": transfer not verified");
        return stored;
    }

    @Override
    public byte[] uploadProgram(String name) {
        requireExtended("program upload");
        if (!OpenAbb.validProgramName(name))
            throw new IllegalArgumentException("program name '" + name + "' is not a RAPID identifier of 1 to 32 characters");
        Reply head = call(OpenAbb.UPLOAD_BEGIN, "upload " + name, name);
        long length = head.natural(1, "length");
        long crc = Checksums.parseHex(head.token(2, "crc32"));
        if (crc < 0) throw new CommsException.Protocol("reply '" + clip(head.text()) + "': crc32 is not 8 hex digits");
        if (length > OpenAbb.MAX_PROGRAM_BYTES) throw new CommsException.Protocol("program " + name + " announced " + length + " bytes: too large");
        byte[] text = new byte[(int) length];
        int off = 0;
        while (off < length) {
            Reply r = call(OpenAbb.UPLOAD_CHUNK, "upload " + name, name, Integer.toString(off));
            if (r.natural(0, "offset") != off) throw new CommsException.Protocol("chunk for offset " + r.data().get(0) + ", expected " + off);
            byte[] chunk;
            try {
                chunk = Base64.getDecoder().decode(r.token(1, "chunk"));
            } catch (IllegalArgumentException e) {
                throw new CommsException.Protocol("upload chunk at " + off + " is not base64");
            }
            if (chunk.length == 0 || off + chunk.length > length)
                throw new CommsException.Protocol("upload chunk at " + off + " has " + chunk.length + " bytes; program has " + length);
            System.arraycopy(chunk, 0, text, off, chunk.length);
            off += chunk.length;
        }
        long got = Checksums.crc32(text);
        if (got != crc)
            throw new CommsException.Protocol("uploaded " + name + " has crc " + Checksums.hex(got) + ", controller announced "
                    + Checksums.hex(crc) + ": transfer corrupted");
        return text;
    }

    @Override
    public List<ProgramInfo> listPrograms() {
        requireExtended("list programs");
        Reply r = call(OpenAbb.LIST_PROGRAMS, "list programs");
        long n = r.natural(0, "count");
        List<ProgramInfo> l = new ArrayList<>();
        for (int i = 0; i < n; i++)
            l.add(new ProgramInfo(r.token(1 + 3 * i, "name"), (int) r.natural(2 + 3 * i, "length"),
                    Checksums.parseHex(r.token(3 + 3 * i, "crc32"))));
        return l;
    }

    @Override
    public void startProgram(long requestId, String name) {
        requireExtended("run program");
        Reply r = call(OpenAbb.RUN_PROGRAM, "run " + name, Long.toString(requestId), name);
        if (r.natural(0, "request id") != requestId) throw new CommsException.Protocol("run reply for another request: " + r.text());
    }

    @Override
    public void stopProgram() {
        requireExtended("stop program");
        call(OpenAbb.STOP_PROGRAM, "stop");
    }

    @Override
    public ControllerStatus readStatus() {
        requireExtended("status");
        Reply r = call(OpenAbb.STATUS, "status");
        ControllerStatus.State st;
        try {
            st = ControllerStatus.State.valueOf(r.token(0, "state").toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new CommsException.Protocol("status reply '" + clip(r.text()) + "': unknown state");
        }
        String prog = r.token(1, "program");
        int errors = (int) r.natural(2, "error count");
        String last = r.token(3, "last error");
        ErrorCode code = last.equals("-") ? null : ErrorCode.fromWire(last).orElse(ErrorCode.INTERNAL);
        double clock = r.number(4, "clock");
        String msg = r.data().size() > 5 ? String.join(" ", r.data().subList(5, r.data().size())) : null;
        return new ControllerStatus(st, prog.equals("-") ? "" : prog, errors, code, msg, clock);
    }

    @Override
    public Vec3 measure() {
        requireExtended("measure");
        Reply r = call(OpenAbb.MEASURE, "measure");
        return new Vec3(Units.mmToM(r.number(0, "x")), Units.mmToM(r.number(1, "y")), Units.mmToM(r.number(2, "z")));
    }

    /**
     * A reading with its conditions: reply {@code x y z clock_s temp_c payload_kg dir1..dirN}
     * (temp_c "NaN" when the controller does not model temperature).
     */
    @Override
    public TrackerReading measureReading() {
        requireExtended("measure");
        Reply r = call(OpenAbb.MEASURE, "measure");
        r.expectAtLeast(6, "measure reply (x y z clock_s temp_c payload_kg dir1..dirN)");
        Vec3 p = new Vec3(Units.mmToM(r.number(0, "x")), Units.mmToM(r.number(1, "y")), Units.mmToM(r.number(2, "z")));
        double t = r.number(3, "clock_s");
        String tempTok = r.token(4, "temp_c");
        double temp = tempTok.equals("NaN") ? Double.NaN : r.number(4, "temp_c");
        double payload = r.number(5, "payload_kg");
        int[] dirs = new int[r.data().size() - 6];
        for (int i = 0; i < dirs.length; i++) {
            String d = r.token(6 + i, "dir" + (i + 1));
            if (!d.equals("1") && !d.equals("-1") && !d.equals("0"))
                throw new CommsException.Protocol("measure reply '" + clip(r.text()) + "': dir" + (i + 1) + " '" + d + "' is not -1, 0 or 1");
            dirs[i] = Integer.parseInt(d);
        }
        return new TrackerReading(p, new PoseConditions(dirs, t, temp, payload));
    }

    /** True once HELLO showed a robopro controller (never makes a request itself: the invoker asks while the link is down). */
    @Override public boolean deduplicatesRequests() { return Boolean.TRUE.equals(extended); }

    @Override public void setReplyTimeout(Duration t) { this.timeout = t; }

    @Override public void reconnect() { channel.reconnect(); }

    @Override public void close() { channel.close(); }

    /** Text for a program's bytes (RAPID files are ASCII/UTF-8). */
    public static String text(byte[] program) { return new String(program, StandardCharsets.UTF_8); }
}
