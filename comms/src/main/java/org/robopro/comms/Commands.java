package org.robopro.comms;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;
import org.robopro.programs.SpeedData;
import org.robopro.programs.ZoneData;

/**
 * The concrete commands (seed paper §2.1, Fig. 3) and factories for them. Each is a small
 * immutable object holding its arguments (SI units); {@link CommandInvoker} runs them.
 */
public final class Commands {
    private Commands() { }

    public static Ping ping() { return new Ping(); }
    public static ReadJoints readJoints() { return new ReadJoints(); }
    public static ReadPose readPose() { return new ReadPose(); }
    public static MoveJoints moveJoints(double[] q) { return new MoveJoints(q); }
    public static MoveLinear moveLinear(Pose wobjTtool) { return new MoveLinear(wobjTtool); }
    public static SetTool setTool(Pose flangeTtool) { return new SetTool(flangeTtool); }
    public static SetWorkObject setWorkObject(Pose baseTwobj) { return new SetWorkObject(baseTwobj); }
    public static SetSpeed setSpeed(SpeedData speed) { return new SetSpeed(speed); }
    public static SetZone setZone(ZoneData zone) { return new SetZone(zone); }
    public static DownloadProgram downloadProgram(String name, byte[] text) { return new DownloadProgram(name, text); }
    public static UploadProgram uploadProgram(String name) { return new UploadProgram(name); }
    public static ListPrograms listPrograms() { return new ListPrograms(); }
    public static StartProgram startProgram(String name) { return new StartProgram(name); }
    public static StopProgram stopProgram() { return new StopProgram(); }
    public static ReadStatus readStatus() { return new ReadStatus(); }
    public static Measure measure() { return new Measure(); }

    /** A tracker reading with the pose's conditions (what a measurement file row needs). */
    public static MeasureReading measureReading() { return new MeasureReading(); }

    static String degrees(double[] qRad) {
        return Arrays.stream(qRad).mapToObj(v -> String.format(Locale.ROOT, "%.3f", Units.radToDeg(v)))
                .collect(Collectors.joining(" ", "[", "] deg"));
    }

    static String pose(Pose p) {
        double[] q = p.quaternion();
        return String.format(Locale.ROOT, "[%.2f %.2f %.2f mm, q %.5f %.5f %.5f %.5f]", Units.mToMm(p.x()),
                Units.mToMm(p.y()), Units.mToMm(p.z()), q[0], q[1], q[2], q[3]);
    }

    public static final class Ping extends ControllerCommand<Void> {
        Ping() { super("ping", RetryPolicy.SAFE); }

        @Override public Void execute(ControllerReceiver r) { r.ping(); return null; }
    }

    public static final class ReadJoints extends ControllerCommand<double[]> {
        ReadJoints() { super("read-joints", RetryPolicy.SAFE); }

        @Override public double[] execute(ControllerReceiver r) { return r.readJoints(); }
    }

    public static final class ReadPose extends ControllerCommand<Pose> {
        ReadPose() { super("read-pose", RetryPolicy.SAFE); }

        @Override public Pose execute(ControllerReceiver r) { return r.readPose(); }
    }

    public static final class MoveJoints extends ControllerCommand<MotionResult> {
        private final double[] q;

        MoveJoints(double[] q) {
            super("move-joints", RetryPolicy.IF_DEDUPLICATED);
            for (double v : q)
                if (!Double.isFinite(v)) throw new IllegalArgumentException("non-finite joint target " + Arrays.toString(q));
            this.q = q.clone();
        }

        public double[] target() { return q.clone(); }

        @Override public MotionResult execute(ControllerReceiver r) { return r.moveJoints(requestId(), q.clone()); }

        @Override protected String arguments() { return degrees(q); }
    }

    public static final class MoveLinear extends ControllerCommand<MotionResult> {
        private final Pose target;

        MoveLinear(Pose wobjTtool) {
            super("move-linear", RetryPolicy.IF_DEDUPLICATED);
            this.target = wobjTtool;
        }

        public Pose target() { return target; }

        @Override public MotionResult execute(ControllerReceiver r) { return r.moveLinear(requestId(), target); }

        @Override protected String arguments() { return pose(target); }
    }

    public static final class SetTool extends ControllerCommand<Void> {
        private final Pose flangeTtool;

        SetTool(Pose flangeTtool) {
            super("set-tool", RetryPolicy.SAFE);
            this.flangeTtool = flangeTtool;
        }

        @Override public Void execute(ControllerReceiver r) { r.setTool(flangeTtool); return null; }

        @Override protected String arguments() { return pose(flangeTtool); }
    }

    public static final class SetWorkObject extends ControllerCommand<Void> {
        private final Pose baseTwobj;

        SetWorkObject(Pose baseTwobj) {
            super("set-wobj", RetryPolicy.SAFE);
            this.baseTwobj = baseTwobj;
        }

        @Override public Void execute(ControllerReceiver r) { r.setWorkObject(baseTwobj); return null; }

        @Override protected String arguments() { return pose(baseTwobj); }
    }

    public static final class SetSpeed extends ControllerCommand<Void> {
        private final SpeedData speed;

        SetSpeed(SpeedData speed) {
            super("set-speed", RetryPolicy.SAFE);
            this.speed = speed;
        }

        @Override public Void execute(ControllerReceiver r) { r.setSpeed(speed); return null; }

        @Override protected String arguments() {
            return String.format(Locale.ROOT, "%.1f mm/s %.1f deg/s", Units.mToMm(speed.vTcp()),
                    Units.radToDeg(speed.vOri()));
        }
    }

    public static final class SetZone extends ControllerCommand<Void> {
        private final ZoneData zone;

        SetZone(ZoneData zone) {
            super("set-zone", RetryPolicy.SAFE);
            this.zone = zone;
        }

        @Override public Void execute(ControllerReceiver r) { r.setZone(zone); return null; }

        @Override protected String arguments() {
            return zone.finep() ? "fine" : String.format(Locale.ROOT, "z%.1f mm", Units.mToMm(zone.pzoneTcp()));
        }
    }

    /** Downloads a program; safe to repeat because the controller stores it only on a verified commit. */
    public static final class DownloadProgram extends ControllerCommand<ProgramInfo> {
        private final String programName;
        private final byte[] text;

        DownloadProgram(String programName, byte[] text) {
            super("download", RetryPolicy.SAFE);
            this.programName = programName;
            this.text = text.clone();
        }

        @Override public ProgramInfo execute(ControllerReceiver r) { return r.downloadProgram(programName, text.clone()); }

        @Override protected String arguments() { return programName + " (" + text.length + " bytes)"; }
    }

    public static final class UploadProgram extends ControllerCommand<byte[]> {
        private final String programName;

        UploadProgram(String programName) {
            super("upload", RetryPolicy.SAFE);
            this.programName = programName;
        }

        @Override public byte[] execute(ControllerReceiver r) { return r.uploadProgram(programName); }

        @Override protected String arguments() { return programName; }
    }

    public static final class ListPrograms extends ControllerCommand<List<ProgramInfo>> {
        ListPrograms() { super("list-programs", RetryPolicy.SAFE); }

        @Override public List<ProgramInfo> execute(ControllerReceiver r) { return r.listPrograms(); }
    }

    public static final class StartProgram extends ControllerCommand<Void> {
        private final String programName;

        StartProgram(String programName) {
            super("start", RetryPolicy.IF_DEDUPLICATED);
            this.programName = programName;
        }

        @Override public Void execute(ControllerReceiver r) { r.startProgram(requestId(), programName); return null; }

        @Override protected String arguments() { return programName; }
    }

    public static final class StopProgram extends ControllerCommand<Void> {
        StopProgram() { super("stop", RetryPolicy.SAFE); }

        @Override public Void execute(ControllerReceiver r) { r.stopProgram(); return null; }
    }

    public static final class ReadStatus extends ControllerCommand<ControllerStatus> {
        ReadStatus() { super("status", RetryPolicy.SAFE); }

        @Override public ControllerStatus execute(ControllerReceiver r) { return r.readStatus(); }
    }

    public static final class Measure extends ControllerCommand<Vec3> {
        Measure() { super("measure", RetryPolicy.SAFE); }

        @Override public Vec3 execute(ControllerReceiver r) { return r.measure(); }
    }

    public static final class MeasureReading extends ControllerCommand<TrackerReading> {
        MeasureReading() { super("measure", RetryPolicy.SAFE); }

        @Override public TrackerReading execute(ControllerReceiver r) { return r.measureReading(); }
    }
}
