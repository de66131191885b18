package org.robopro.comms.sim;

import java.io.ByteArrayOutputStream;
import java.util.Base64;
import java.util.List;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.TrackerReading;
import org.robopro.comms.MotionResult;
import org.robopro.comms.ProgramInfo;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ZoneData;
import org.robopro.comms.protocol.Checksums;
import org.robopro.comms.protocol.OpenAbb;
import org.robopro.comms.protocol.Request;
import org.robopro.comms.protocol.Request.RequestException;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated controller's side of the protocol: one request text in, one reply text out,
 * as RAPID/SERVER.mod answers (plus robopro's extension). Never throws: a malformed request,
 * a refused one or an internal failure all become an {@code ok = 0} reply with an error code.
 * Program transfers live in a {@link Session} (one per connection), so a transfer cut off by
 * a dropped link leaves nothing stored.
 */
public final class ProtocolHandler {
    private static final Logger LOG = LoggerFactory.getLogger(ProtocolHandler.class);

    private final SimulatedController controller;

    public ProtocolHandler(SimulatedController controller) { this.controller = controller; }

    public SimulatedController controller() { return controller; }

    /** Per-connection state: an open program download. */
    public static final class Session {
        String name;
        int length;
        long crc;
        ByteArrayOutputStream received;
        boolean closeRequested;

        /** True after instruction 99: the transport should drop this connection without replying. */
        public boolean closeRequested() { return closeRequested; }
    }

    public Session newSession() { return new Session(); }

    /** Handles one request; returns the reply text without terminator, or null for "close, no reply". */
    public String handle(Session session, String text) {
        int code = -1;
        try {
            Request r = Request.parse(text);
            code = r.code();
            String data = dispatch(session, r);
            if (data == null) return null;
            return code + " " + OpenAbb.SERVER_OK + " " + data;
        } catch (RequestException e) {
            int c = e.instruction() >= 0 ? e.instruction() : Math.max(code, 0);
            controller.recordError(e.error(), e.getMessage());
            return org.robopro.comms.protocol.Reply.error(c, e.error(), e.getMessage());
        } catch (CommsException.Refused e) {
            controller.recordError(e.code(), e.getMessage());
            String msg = e.getMessage().startsWith(e.code().toString()) ? e.getMessage().substring(e.code().toString().length()).strip() : e.getMessage();
            return org.robopro.comms.protocol.Reply.error(code, e.code(), msg);
        } catch (RuntimeException e) {
            LOG.warn("internal error handling '{}'", text, e);
            controller.recordError(ErrorCode.INTERNAL, String.valueOf(e));
            return org.robopro.comms.protocol.Reply.error(Math.max(code, 0), ErrorCode.INTERNAL, String.valueOf(e));
        }
    }

    private String dispatch(Session s, Request r) {
        SimulatedController c = controller;
        switch (r.code()) {
            case OpenAbb.PING -> { r.expectCount(0); c.ping(); return ""; }
            case OpenAbb.MOVE_CARTESIAN -> { r.expectCount(7); c.moveLinear(0, pose(r, 0)); return ""; }
            case OpenAbb.MOVE_JOINTS -> { r.expectCount(6); c.moveJoints(0, joints(r, 0)); return ""; }
            case OpenAbb.GET_CARTESIAN -> { r.expectCount(0); return pose(c.readPose()); }
            case OpenAbb.GET_JOINTS -> {
                r.expectCount(0);
                double[] q = c.readJoints();
                StringBuilder sb = new StringBuilder();
                for (int i = 0; i < q.length; i++) sb.append(i == 0 ? "" : " ").append(OpenAbb.num(Units.radToDeg(q[i]), 4));
                return sb.toString();
            }
            case OpenAbb.GET_EXTERNAL_AXES -> { r.expectCount(0); return "9E+09 9E+09 9E+09 9E+09 9E+09 9E+09"; }
            case OpenAbb.SET_TOOL -> { r.expectCount(7); c.setTool(pose(r, 0)); return ""; }
            case OpenAbb.SET_WOBJ -> { r.expectCount(7); c.setWorkObject(pose(r, 0)); return ""; }
            case OpenAbb.SET_SPEED -> {
                r.expectCount(4, 2);
                SpeedData old = c.speed();
                double tcp = r.number(0, "v_tcp"), ori = r.number(1, "v_ori");
                double leax = r.count() == 4 ? r.number(2, "v_leax") : Units.mToMm(old.vLeax());
                double reax = r.count() == 4 ? r.number(3, "v_reax") : Units.radToDeg(old.vReax());
                if (!(tcp > 0 && ori > 0 && leax >= 0 && reax >= 0) || tcp > 10_000 || ori > 10_000)
                    throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "speed " + tcp + " mm/s, " + ori
                            + " deg/s: must be > 0 and <= 10000");
                c.setSpeed(new SpeedData(Units.mmToM(tcp), Units.degToRad(ori), Units.mmToM(leax), Units.degToRad(reax)));
                return "";
            }
            case OpenAbb.SET_ZONE -> {
                r.expectCount(4);
                double fine = r.number(0, "finep");
                if (fine != 0 && fine != 1) throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "finep must be 0 or 1, got " + fine);
                double a = r.number(1, "pzone_tcp"), b = r.number(2, "pzone_ori"), d = r.number(3, "zone_ori");
                if (a < 0 || b < 0 || d < 0) throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "zone sizes must be >= 0");
                c.setZone(fine == 1 ? ZoneData.FINE : ZoneData.flyBy(Units.mmToM(a), Units.mmToM(b), Units.degToRad(d)));
                return "";
            }
            case OpenAbb.BUFFER_ADD -> { r.expectCount(7); c.bufferAdd(pose(r, 0)); return ""; }
            case OpenAbb.BUFFER_CLEAR -> { r.expectCount(0); c.bufferClear(); return ""; }
            case OpenAbb.BUFFER_SIZE -> { r.expectCount(0); return Integer.toString(c.bufferSize()); }
            case OpenAbb.BUFFER_EXECUTE -> { r.expectCount(0); c.bufferExecute(); return ""; }
            case OpenAbb.EXTERNAL_AXES_MOVE -> throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "the simulated robot has no external axes");
            case OpenAbb.CIRCULAR_POINT, OpenAbb.CIRCULAR_MOVE ->
                    throw new RequestException(r.code(), ErrorCode.UNKNOWN_INSTRUCTION, "circular moves are not simulated");
            case OpenAbb.ROBOT_INFO -> { r.expectCount(0); return "ROBOPRO-SIM*robopro 0.1*" + c.robot().name(); }
            case OpenAbb.CLOSE -> { r.expectCount(0); s.closeRequested = true; return null; }
            // ---------------- robopro extension
            case OpenAbb.HELLO -> { r.expectCount(0); return "robopro 1 " + c.robot().name() + " " + c.robot().dof(); }
            case OpenAbb.MOVE_CARTESIAN_TAGGED -> {
                r.expectCount(8);
                long id = r.natural(0, "request id");
                MotionResult m = c.moveLinear(id, pose(r, 1));
                return id + " " + OpenAbb.num(m.motionTimeS(), 4);
            }
            case OpenAbb.MOVE_JOINTS_TAGGED -> {
                r.expectCount(7);
                long id = r.natural(0, "request id");
                MotionResult m = c.moveJoints(id, joints(r, 1));
                return id + " " + OpenAbb.num(m.motionTimeS(), 4);
            }
            case OpenAbb.STATUS -> {
                r.expectCount(0);
                ControllerStatus st = c.readStatus();
                return st.state() + " " + (st.program().isEmpty() ? "-" : st.program()) + " " + st.errorCount() + " "
                        + (st.lastError() == null ? "-" : st.lastError().wire()) + " " + OpenAbb.num(st.clockS(), 4)
                        + (st.lastErrorMessage() == null ? "" : " " + st.lastErrorMessage().replace('\n', ' ').replace('#', ' '));
            }
            case OpenAbb.LIST_PROGRAMS -> {
                r.expectCount(0);
                List<ProgramInfo> l = c.listPrograms();
                StringBuilder sb = new StringBuilder().append(l.size());
                for (ProgramInfo p : l) sb.append(' ').append(p.name()).append(' ').append(p.length()).append(' ').append(Checksums.hex(p.crc32()));
                return sb.toString();
            }
            case OpenAbb.DOWNLOAD_BEGIN -> {
                r.expectCount(3);
                String name = r.params().get(0);
                if (!OpenAbb.validProgramName(name))
                    throw new RequestException(r.code(), ErrorCode.BAD_PROGRAM_NAME, "'" + name + "' is not a RAPID identifier of 1 to 32 characters");
                long len = r.natural(1, "length");
                if (len > OpenAbb.MAX_PROGRAM_BYTES)
                    throw new RequestException(r.code(), ErrorCode.PROGRAM_TOO_LARGE, len + " bytes > " + OpenAbb.MAX_PROGRAM_BYTES);
                long crc = Checksums.parseHex(r.params().get(2));
                if (crc < 0) throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "crc32 '" + r.params().get(2) + "' is not 8 hex digits");
                s.name = name;
                s.length = (int) len;
                s.crc = crc;
                s.received = new ByteArrayOutputStream((int) len);
                return name;
            }
            case OpenAbb.DOWNLOAD_CHUNK -> {
                r.expectCount(2);
                if (s.received == null) throw new RequestException(r.code(), ErrorCode.TRANSFER_STATE, "no download open (send 45 first)");
                long off = r.natural(0, "offset");
                byte[] bytes;
                try {
                    bytes = Base64.getDecoder().decode(r.params().get(1));
                } catch (IllegalArgumentException e) {
                    throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "chunk is not base64: " + e.getMessage());
                }
                int have = s.received.size();
                if (off + bytes.length == have && off < have) return Integer.toString(have); // a repeated chunk: already stored
                if (off != have)
                    throw new RequestException(r.code(), ErrorCode.TRANSFER_STATE, "chunk at offset " + off + ", expected " + have);
                if (have + bytes.length > s.length)
                    throw new RequestException(r.code(), ErrorCode.CHECKSUM_MISMATCH, "more bytes than the announced " + s.length);
                s.received.writeBytes(bytes);
                return Integer.toString(s.received.size());
            }
            case OpenAbb.DOWNLOAD_COMMIT -> {
                r.expectCount(0);
                if (s.received == null) {
                    // A repeated commit whose first reply was lost: answer again if that program is stored.
                    if (s.name != null) {
                        var p = c.programInfo(s.name);
                        if (p.isPresent() && p.get().crc32() == s.crc && p.get().length() == s.length)
                            return p.get().name() + " " + p.get().length() + " " + Checksums.hex(p.get().crc32());
                    }
                    throw new RequestException(r.code(), ErrorCode.TRANSFER_STATE, "no download open");
                }
                byte[] text = s.received.toByteArray();
                s.received = null;
                ProgramInfo p = c.storeProgram(s.name, text, s.length, s.crc);
                return p.name() + " " + p.length() + " " + Checksums.hex(p.crc32());
            }
            case OpenAbb.UPLOAD_BEGIN -> {
                r.expectCount(1);
                String name = r.params().get(0);
                var p = c.programInfo(name).orElseThrow(() -> new RequestException(r.code(), ErrorCode.NO_SUCH_PROGRAM, "no program named '" + Request.clip(name) + "'"));
                return p.name() + " " + p.length() + " " + Checksums.hex(p.crc32());
            }
            case OpenAbb.UPLOAD_CHUNK -> {
                r.expectCount(2);
                String name = r.params().get(0);
                long off = r.natural(1, "offset");
                byte[] text;
                try {
                    text = c.uploadProgram(name);
                } catch (CommsException.Refused e) {
                    throw new RequestException(r.code(), e.code(), "no program named '" + Request.clip(name) + "'");
                }
                if (off > text.length) throw new RequestException(r.code(), ErrorCode.TRANSFER_STATE, "offset " + off + " beyond length " + text.length);
                int n = (int) Math.min(OpenAbb.CHUNK_BYTES, text.length - off);
                byte[] chunk = java.util.Arrays.copyOfRange(text, (int) off, (int) off + n);
                return off + " " + (n == 0 ? "-" : Base64.getEncoder().encodeToString(chunk));
            }
            case OpenAbb.RUN_PROGRAM -> {
                r.expectCount(2);
                long id = r.natural(0, "request id");
                c.startProgram(id, r.params().get(1));
                return Long.toString(id);
            }
            case OpenAbb.STOP_PROGRAM -> { r.expectCount(0); c.stopProgram(); return ""; }
            case OpenAbb.MEASURE -> {
                r.expectCount(0);
                // x y z (mm), then the conditions: clock_s temp_c|NaN payload_kg dir1..dirN
                TrackerReading m = c.measureReading();
                Vec3 p = m.position();
                StringBuilder sb = new StringBuilder();
                sb.append(OpenAbb.num(Units.mToMm(p.x()), 4)).append(' ').append(OpenAbb.num(Units.mToMm(p.y()), 4)).append(' ')
                        .append(OpenAbb.num(Units.mToMm(p.z()), 4)).append(' ').append(OpenAbb.num(m.conditions().timeS(), 3)).append(' ')
                        .append(Double.isNaN(m.conditions().tempC()) ? "NaN" : OpenAbb.num(m.conditions().tempC(), 3)).append(' ')
                        .append(OpenAbb.num(m.conditions().payloadKg(), 3));
                for (int d : m.conditions().directions()) sb.append(' ').append(d);
                return sb.toString();
            }
            default -> throw new RequestException(r.code(), ErrorCode.UNKNOWN_INSTRUCTION, "instruction " + r.code() + " is not known");
        }
    }

    private static double[] joints(Request r, int first) {
        double[] q = new double[6];
        for (int i = 0; i < 6; i++) q[i] = Units.degToRad(r.number(first + i, "joint " + (i + 1)));
        return q;
    }

    /** x y z (mm) q1 q2 q3 q4 (q1 scalar) starting at parameter {@code first}. */
    static Pose pose(Request r, int first) {
        double x = r.number(first, "x"), y = r.number(first + 1, "y"), z = r.number(first + 2, "z");
        double q1 = r.number(first + 3, "q1"), q2 = r.number(first + 4, "q2"), q3 = r.number(first + 5, "q3"), q4 = r.number(first + 6, "q4");
        double n = Math.sqrt(q1 * q1 + q2 * q2 + q3 * q3 + q4 * q4);
        // abb.py sends 5 decimals, so a unit quaternion may be off by ~1e-5.
        if (Math.abs(n - 1) > 1e-3)
            throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "quaternion (" + q1 + ", " + q2 + ", " + q3 + ", " + q4 + ") has norm " + n + ", not 1");
        if (Math.abs(x) > 1e6 || Math.abs(y) > 1e6 || Math.abs(z) > 1e6)
            throw new RequestException(r.code(), ErrorCode.BAD_VALUE, "position beyond 1000 m");
        return Pose.fromQuaternion(q1, q2, q3, q4, Units.mmToM(x), Units.mmToM(y), Units.mmToM(z));
    }

    /** Pose as SERVER.mod's instruction 3 sends it (more decimals: the simulator's values are exact). */
    static String pose(Pose p) {
        double[] q = p.quaternion();
        return OpenAbb.num(Units.mToMm(p.x()), 3) + " " + OpenAbb.num(Units.mToMm(p.y()), 3) + " " + OpenAbb.num(Units.mToMm(p.z()), 3)
                + " " + OpenAbb.num(q[0], 6) + " " + OpenAbb.num(q[1], 6) + " " + OpenAbb.num(q[2], 6) + " " + OpenAbb.num(q[3], 6);
    }
}
