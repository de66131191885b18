package org.robopro.comms.sim;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicLong;
import org.robopro.calibration.PoseConditions;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerReceiver;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.ErrorCode;
import org.robopro.comms.MotionResult;
import org.robopro.comms.ProgramInfo;
import org.robopro.programs.SpeedData;
import org.robopro.comms.TrackerReading;
import org.robopro.programs.ZoneData;
import org.robopro.comms.protocol.Checksums;
import org.robopro.comms.protocol.OpenAbb;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated IRB-2000 controller: joint state, tool, work object, speed, zone, stored
 * programs, a program runner and a laser tracker, on top of a {@link SimulatedRobot}.
 *
 * <p>Motions take simulated time computed from the joint speed limits and the TCP speed (no
 * sleeping unless {@code realtime}); targets outside the joint limits or out of reach are
 * refused with {@link CommsException.Refused}. Motions and program starts carrying a request
 * id (&gt; 0) are executed at most once: a repeated id gets the first outcome again. Thread-safe
 * (every operation holds the controller's lock); it is also a {@link ControllerReceiver}, so
 * tests and the workbench can drive it in process.
 */
public final class SimulatedController implements ControllerReceiver {
    private static final Logger LOG = LoggerFactory.getLogger(SimulatedController.class);
    private static final int DEDUP_WINDOW = 50_000;
    /** SERVER.mod's speed after Initialize: 100 mm/s, 50 deg/s (not RAPID's predefined v100). */
    static final SpeedData INITIAL_SPEED = SpeedData.ofRapid(100, 50, 0, 0);

    /**
     * Settings of the simulated controller (the tracker's pose and noise belong to the robot).
     *
     * @param seed      seed of the tracker noise
     * @param realtime  sleep for each motion's time
     * @param payloadKg mass carried at the flange (reported with each tracker reading)
     */
    public record Settings(long seed, boolean realtime, double payloadKg) {
        public Settings {
            if (!(payloadKg >= 0) || !Double.isFinite(payloadKg)) throw new IllegalArgumentException("payload " + payloadKg + " kg must be >= 0");
        }

        public static Settings defaults(long seed) { return new Settings(seed, false, 0); }

        public Settings withRealtime(boolean rt) { return new Settings(seed, rt, payloadKg); }

        public Settings withPayload(double kg) { return new Settings(seed, realtime, kg); }
    }

    private final SimulatedRobot robot;
    private final Settings settings;
    private final Random noise;
    private final ProgramInterpreter interpreter;

    private double[] q;
    private final int[] lastDirection;
    private Pose flangeTtool = Pose.IDENTITY;
    private Pose baseTwobj = Pose.IDENTITY;
    private SpeedData speed = INITIAL_SPEED;
    private ZoneData zone = ZoneData.FINE;
    private double clockS;
    private final Map<String, byte[]> programs = new TreeMap<>();
    private final LinkedHashMap<Long, Object> outcomes = new LinkedHashMap<>(1024, 0.75f, false) {
        private static final long serialVersionUID = 1L;

        @Override protected boolean removeEldestEntry(Map.Entry<Long, Object> e) { return size() > DEDUP_WINDOW; }
    };
    private final List<Pose> cartesianBuffer = new ArrayList<>();
    private final List<SpeedData> cartesianBufferSpeeds = new ArrayList<>();

    private ControllerStatus.State state = ControllerStatus.State.IDLE;
    private String currentProgram = "";
    private int errorCount;
    private ErrorCode lastError;
    private String lastErrorMessage;
    private volatile boolean stopRequested;
    private Thread runner;

    private final AtomicLong motionsExecuted = new AtomicLong();
    private final Map<Long, Integer> executionsById = new LinkedHashMap<>();

    public SimulatedController(SimulatedRobot robot, Settings settings, ProgramInterpreter interpreter) {
        this.robot = robot;
        this.settings = settings;
        this.noise = new Random(settings.seed() ^ 0x5DEECE66DL);
        this.interpreter = interpreter;
        this.q = new double[robot.dof()];
        this.lastDirection = new int[robot.dof()];
        for (int i = 0; i < q.length; i++) {
            double lo = robot.lowerLimits()[i], hi = robot.upperLimits()[i];
            q[i] = Math.min(hi, Math.max(lo, 0)); // zero position, inside the limits
        }
    }

    public SimulatedController(SimulatedRobot robot, Settings settings) {
        this(robot, settings, new RapidProgramInterpreter());
    }

    public SimulatedRobot robot() { return robot; }

    public Settings settings() { return settings; }

    // ---------------------------------------------------------------- state and settings

    @Override public synchronized void ping() { }

    @Override public synchronized double[] readJoints() { return q.clone(); }

    /** The tool seen from the work object, by the controller's nominal model (CRobT). */
    @Override public synchronized Pose readPose() {
        return baseTwobj.inverse().times(robot.nominalFlange(q)).times(flangeTtool);
    }

    @Override public synchronized void setTool(Pose t) { flangeTtool = t; }

    @Override public synchronized void setWorkObject(Pose w) { baseTwobj = w; }

    @Override
    public synchronized void setSpeed(SpeedData s) {
        if (!(s.vTcp() > 0 && s.vOri() > 0))
            throw new IllegalArgumentException("the controller moves at TCP and reorientation speeds > 0, not " + s);
        speed = s;
    }

    @Override public synchronized void setZone(ZoneData z) { zone = z; }

    public synchronized Pose tool() { return flangeTtool; }

    public synchronized Pose workObject() { return baseTwobj; }

    public synchronized SpeedData speed() { return speed; }

    public synchronized ZoneData zone() { return zone; }

    public synchronized double clockS() { return clockS; }

    /** How many motions were executed (for the no-duplicate guarantees). */
    public long motionsExecuted() { return motionsExecuted.get(); }

    /** How many times the motion with this request id was executed (0 or 1, if the guarantee holds). */
    public synchronized int executions(long requestId) { return executionsById.getOrDefault(requestId, 0); }

    /** Copy of per-request-id execution counts of tagged motions. */
    public synchronized Map<Long, Integer> executionCounts() { return new LinkedHashMap<>(executionsById); }

    // ---------------------------------------------------------------- motion

    @Override
    public MotionResult moveJoints(long requestId, double[] target) {
        return deduplicated(requestId, () -> executeJointMove(target));
    }

    @Override
    public MotionResult moveLinear(long requestId, Pose wobjTtool) {
        return deduplicated(requestId, () -> executeLinearMove(wobjTtool, speed));
    }

    private synchronized MotionResult deduplicated(long requestId, java.util.function.Supplier<MotionResult> motion) {
        if (requestId > 0) {
            Object prior = outcomes.get(requestId);
            if (prior instanceof MotionResult m) return m;
            if (prior instanceof CommsException.Refused r) throw new CommsException.Refused(r.code(), stripCode(r));
        }
        if (state == ControllerStatus.State.RUNNING)
            throw refuse(requestId, ErrorCode.BUSY, "program " + currentProgram + " is running; stop it first");
        try {
            MotionResult r = motion.get();
            if (requestId > 0) {
                outcomes.put(requestId, r);
                executionsById.merge(requestId, 1, Integer::sum);
            }
            return r;
        } catch (CommsException.Refused e) {
            if (requestId > 0) outcomes.put(requestId, e);
            throw e;
        }
    }

    private CommsException.Refused refuse(long requestId, ErrorCode code, String msg) {
        CommsException.Refused e = new CommsException.Refused(code, msg);
        if (requestId > 0) outcomes.put(requestId, e);
        return e;
    }

    private static String stripCode(CommsException.Refused r) {
        String m = r.getMessage();
        String prefix = r.code().toString() + " ";
        return m.startsWith(prefix) ? m.substring(prefix.length()) : m;
    }

    /** Checks a joint target against the limits; refuses naming the joint. */
    private void checkLimits(double[] target, String what) {
        if (target.length != robot.dof())
            throw new CommsException.Refused(ErrorCode.BAD_VALUE, what + " has " + target.length + " joints, robot has " + robot.dof());
        for (int i = 0; i < target.length; i++) {
            double lo = robot.lowerLimits()[i], hi = robot.upperLimits()[i];
            if (!Double.isFinite(target[i]))
                throw new CommsException.Refused(ErrorCode.BAD_VALUE, what + ": joint " + (i + 1) + " not finite");
            if (target[i] < lo - 1e-9 || target[i] > hi + 1e-9)
                throw new CommsException.Refused(ErrorCode.JOINT_LIMIT, String.format(Locale.ROOT,
                        "%s: joint %d at %.3f deg outside %.3f .. %.3f deg", what, i + 1, Units.radToDeg(target[i]),
                        Units.radToDeg(lo), Units.radToDeg(hi)));
        }
    }

    private MotionResult executeJointMove(double[] target) {
        return executeJointMove(target, speed, Double.NaN);
    }

    /** MoveAbsJ / MoveJ: joint interpolation, as slow as the slowest joint, the TCP speed or {@code \T} demand. */
    private MotionResult executeJointMove(double[] target, SpeedData s, double timeS) {
        checkLimits(target, "joint target");
        double t = jointTime(q, target);
        double tcp = robot.nominalFlange(q).times(flangeTtool).distanceTo(robot.nominalFlange(target).times(flangeTtool));
        t = Math.max(t, Double.isFinite(timeS) ? timeS : tcp / s.vTcp());
        return finishMotion(target, t, q);
    }

    private double jointTime(double[] from, double[] to) {
        double t = 0;
        double[] v = robot.maxSpeeds();
        for (int i = 0; i < from.length; i++) t = Math.max(t, Math.abs(to[i] - from[i]) / v[i]);
        return t;
    }

    /** The TCP's path in base coordinates, s from 0 (start) to 1 (target). */
    private interface ToolPath {
        Pose baseTtool(double s);
    }

    /** MoveL: straight TCP path, orientation interpolated; every sample must be reachable within limits. */
    private MotionResult executeLinearMove(Pose wobjTtool, SpeedData s) {
        return executeLinear(baseTwobj.times(wobjTtool), s, Double.NaN);
    }

    private MotionResult executeLinear(Pose baseTtool1, SpeedData s, double timeS) {
        Pose baseTtool0 = robot.nominalFlange(q).times(flangeTtool);
        Vec3 rv = baseTtool0.inverse().times(baseTtool1).rotationVector();
        double angle = rv.norm();
        Vec3 p0 = baseTtool0.position(), p1 = baseTtool1.position();
        ToolPath path = sk -> Pose.translation(p0.plus(p1.minus(p0).times(sk)))
                .times(rotationOnly(angle < 1e-12 ? baseTtool0 : baseTtool0.times(Pose.rotAxis(rv, angle * sk))));
        return executePath(path, baseTtool1, p1.minus(p0).norm(), angle, s, timeS, "linear");
    }

    /**
     * MoveC: the TCP on the circle through start, CirPoint and ToPoint, from the start through the
     * CirPoint to the ToPoint; the orientation turns uniformly from the start's to the ToPoint's.
     * Circle centre from the circumscribed-circle formula (centre = C + ((|a|²b − |b|²a) × (a × b)) / (2|a × b|²),
     * a = A − C, b = B − C).
     */
    private MotionResult executeCircular(Pose baseTtoolCirc, Pose baseTtool1, SpeedData s, double timeS) {
        Pose baseTtool0 = robot.nominalFlange(q).times(flangeTtool);
        Vec3 p0 = baseTtool0.position(), pc = baseTtoolCirc.position(), p2 = baseTtool1.position();
        Vec3 u = pc.minus(p0), v = p2.minus(p0), nrm = u.cross(v);
        if (nrm.norm() < 1e-6 * Math.max(1e-3, u.norm() * v.norm()) || u.norm() < 1e-4 || v.norm() < 1e-4 || pc.minus(p2).norm() < 1e-4)
            throw new CommsException.Refused(ErrorCode.PATH_UNREACHABLE,
                    "circular move: start, CirPoint and ToPoint are (nearly) on one line or coincide; no circle through them");
        Vec3 a = p0.minus(p2), b = pc.minus(p2), axb = a.cross(b);
        Vec3 centre = p2.plus(b.times(a.dot(a)).minus(a.times(b.dot(b))).cross(axb).times(1 / (2 * axb.dot(axb))));
        double r = p0.minus(centre).norm();
        Vec3 n = nrm.times(1 / nrm.norm());
        Vec3 e1 = p0.minus(centre).times(1 / r), e2 = n.cross(e1);
        double phiC = angleIn(pc.minus(centre), e1, e2), phi2 = angleIn(p2.minus(centre), e1, e2);
        if (!(phiC > 0 && phiC < phi2)) throw new IllegalStateException("circle construction: CirPoint angle " + phiC + " not before " + phi2);
        Vec3 rv = baseTtool0.inverse().times(baseTtool1).rotationVector();
        double angle = rv.norm();
        ToolPath path = sk -> Pose.translation(centre.plus(e1.times(r * Math.cos(sk * phi2))).plus(e2.times(r * Math.sin(sk * phi2))))
                .times(rotationOnly(angle < 1e-12 ? baseTtool0 : baseTtool0.times(Pose.rotAxis(rv, angle * sk))));
        return executePath(path, baseTtool1, r * phi2, angle, s, timeS, "circular");
    }

    /** Angle of {@code d} in the plane spanned by e1, e2, in [0, 2π). */
    private static double angleIn(Vec3 d, Vec3 e1, Vec3 e2) {
        double phi = Math.atan2(d.dot(e2), d.dot(e1));
        return phi < 0 ? phi + 2 * Math.PI : phi;
    }

    private static Pose rotationOnly(Pose p) { return Pose.of(p.rotationRowMajor(), 0, 0, 0); }

    /** Follows a TCP path sampled every 5 mm / 2°; refuses it (without moving) if any sample is unreachable, out of limits, or a joint jumps. */
    private MotionResult executePath(ToolPath path, Pose baseTtool1, double lengthM, double angle, SpeedData s, double timeS, String what) {
        Pose toolTflange = flangeTtool.inverse();
        Optional<double[]> end = robot.inverse(baseTtool1.times(toolTflange), q);
        if (end.isEmpty())
            throw new CommsException.Refused(ErrorCode.UNREACHABLE, String.format(Locale.ROOT,
                    "target (%.2f, %.2f, %.2f) mm (base frame) is out of reach", Units.mToMm(baseTtool1.x()), Units.mToMm(baseTtool1.y()),
                    Units.mToMm(baseTtool1.z())));
        checkLimits(end.get(), what + " target");
        int n = (int) Math.min(4000, Math.max(1, Math.ceil(Math.max(lengthM / 0.005, angle / Math.toRadians(2)))));
        double[] qi = q, prev = q;
        double jointBound = 0;
        for (int k = 1; k <= n; k++) {
            double sk = (double) k / n;
            Pose pk = k == n ? baseTtool1 : path.baseTtool(sk);
            Optional<double[]> sol = robot.inverse(pk.times(toolTflange), qi);
            if (sol.isEmpty())
                throw new CommsException.Refused(ErrorCode.PATH_UNREACHABLE, String.format(Locale.ROOT,
                        "%s path leaves the workspace at %.0f %% of the way", what, 100 * sk));
            double[] qk = sol.get();
            for (int i = 0; i < qk.length; i++) {
                if (Math.abs(qk[i] - qi[i]) > 0.5)
                    throw new CommsException.Refused(ErrorCode.PATH_UNREACHABLE, String.format(Locale.ROOT,
                            "%s path passes a singularity near %.0f %% of the way (joint %d jumps)", what, 100 * sk, i + 1));
            }
            try {
                checkLimits(qk, what + " path");
            } catch (CommsException.Refused e) {
                throw new CommsException.Refused(ErrorCode.PATH_UNREACHABLE, e.getMessage().substring(e.code().toString().length() + 1));
            }
            jointBound += jointTime(qi, qk);
            prev = qi;
            qi = qk;
        }
        double t = Math.max(jointBound, Double.isFinite(timeS) ? timeS : Math.max(lengthM / s.vTcp(), angle / s.vOri()));
        return finishMotion(qi, t, prev);
    }

    /**
     * Ends a motion at {@code target}. Each joint's approach direction is the sign of its last
     * change before arriving (from {@code approachFrom}, the previous path sample), kept when the
     * joint did not move.
     */
    private MotionResult finishMotion(double[] target, double t, double[] approachFrom) {
        for (int i = 0; i < q.length; i++) {
            double d = target[i] - approachFrom[i];
            if (Math.abs(d) < 1e-12) d = target[i] - q[i];
            if (Math.abs(d) > 1e-12) lastDirection[i] = d > 0 ? 1 : -1;
        }
        q = target.clone();
        clockS += t;
        motionsExecuted.incrementAndGet();
        if (settings.realtime() && t > 0) {
            try {
                Thread.sleep(Duration.ofNanos((long) (t * 1e9)).toMillis());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        return new MotionResult(t);
    }

    // ---------------------------------------------------------------- open_abb buffer (30-33)

    public synchronized int bufferAdd(Pose wobjTtool) {
        if (cartesianBuffer.size() < 512) {
            cartesianBuffer.add(wobjTtool);
            cartesianBufferSpeeds.add(speed);
        }
        return cartesianBuffer.size();
    }

    public synchronized void bufferClear() {
        cartesianBuffer.clear();
        cartesianBufferSpeeds.clear();
    }

    public synchronized int bufferSize() { return cartesianBuffer.size(); }

    public synchronized MotionResult bufferExecute() {
        if (state == ControllerStatus.State.RUNNING) throw new CommsException.Refused(ErrorCode.BUSY, "program running");
        double t = 0;
        for (int i = 0; i < cartesianBuffer.size(); i++) t += executeLinearMove(cartesianBuffer.get(i), cartesianBufferSpeeds.get(i)).motionTimeS();
        return new MotionResult(t);
    }

    // ---------------------------------------------------------------- tracker

    /** Laser tracker reading: the target on the physical robot's tool, tracker frame, with noise. */
    @Override
    public synchronized Vec3 measure() { return measureReading().position(); }

    /** A tracker reading with the conditions it was taken under (directions, clock, temperature, payload). */
    @Override
    public synchronized TrackerReading measureReading() {
        PoseConditions c = conditions();
        return new TrackerReading(robot.measure(q, c, noise), c);
    }

    /** The conditions now: approach directions, clock, temperature (warm-up when the robot is thermal, else NaN), payload. */
    public synchronized PoseConditions conditions() {
        return new PoseConditions(lastDirection.clone(), clockS, robot.thermal() ? SimEffects.warmupC(clockS) : Double.NaN,
                settings.payloadKg());
    }

    /** Sign of each joint's last motion (1, -1, 0 before any motion). */
    public synchronized int[] lastDirection() { return lastDirection.clone(); }

    // ---------------------------------------------------------------- programs

    /** Most programs the controller stores (a real controller's program memory is finite too). */
    public static final int MAX_PROGRAMS = 256;
    /** Most bytes of program text stored in all. */
    public static final long MAX_STORED_BYTES = 64L * 1024 * 1024;

    /**
     * Stores a program if its length and CRC-32 match what the sender announced and it parses;
     * otherwise stores nothing. Replaces a stored program of the same name.
     */
    public synchronized ProgramInfo storeProgram(String name, byte[] text, int announcedLength, long announcedCrc) {
        if (!OpenAbb.validProgramName(name))
            throw new CommsException.Refused(ErrorCode.BAD_PROGRAM_NAME, "'" + name + "' is not a RAPID identifier of 1 to 32 characters");
        long crc = Checksums.crc32(text);
        if (text.length != announcedLength || crc != announcedCrc)
            throw new CommsException.Refused(ErrorCode.CHECKSUM_MISMATCH, "received " + text.length + " bytes, crc "
                    + Checksums.hex(crc) + "; sender announced " + announcedLength + " bytes, crc " + Checksums.hex(announcedCrc)
                    + "; nothing stored");
        if (!programs.containsKey(name) && programs.size() >= MAX_PROGRAMS)
            throw new CommsException.Refused(ErrorCode.STORAGE_FULL, "the controller holds " + programs.size()
                    + " programs, its limit; replace one (same name) or restart the controller; nothing stored");
        long total = text.length;
        for (var e : programs.entrySet()) if (!e.getKey().equals(name)) total += e.getValue().length;
        if (total > MAX_STORED_BYTES)
            throw new CommsException.Refused(ErrorCode.STORAGE_FULL, "storing " + name + " would take the programs to "
                    + total + " bytes, over the controller's " + MAX_STORED_BYTES + "; nothing stored");
        String problem = interpreter.parseProblem(new String(text, StandardCharsets.UTF_8), name);
        if (problem != null) throw new CommsException.Refused(ErrorCode.PROGRAM_SYNTAX, name + ": " + problem + "; nothing stored");
        programs.put(name, text.clone());
        return new ProgramInfo(name, text.length, crc);
    }

    @Override
    public ProgramInfo downloadProgram(String name, byte[] text) {
        return storeProgram(name, text, text.length, Checksums.crc32(text));
    }

    @Override
    public synchronized byte[] uploadProgram(String name) {
        byte[] p = programs.get(name);
        if (p == null) throw new CommsException.Refused(ErrorCode.NO_SUCH_PROGRAM, "no program named '" + name + "'");
        return p.clone();
    }

    public synchronized Optional<ProgramInfo> programInfo(String name) {
        byte[] p = programs.get(name);
        return p == null ? Optional.empty() : Optional.of(new ProgramInfo(name, p.length, Checksums.crc32(p)));
    }

    @Override
    public synchronized List<ProgramInfo> listPrograms() {
        List<ProgramInfo> l = new ArrayList<>();
        for (var e : programs.entrySet()) l.add(new ProgramInfo(e.getKey(), e.getValue().length, Checksums.crc32(e.getValue())));
        return l;
    }

    @Override
    public synchronized void startProgram(long requestId, String name) {
        if (requestId > 0) {
            Object prior = outcomes.get(requestId);
            if (prior instanceof Boolean) return;
            if (prior instanceof CommsException.Refused r) throw new CommsException.Refused(r.code(), stripCode(r));
        }
        if (state == ControllerStatus.State.RUNNING)
            throw refuse(requestId, ErrorCode.BUSY, "program " + currentProgram + " is already running");
        byte[] text = programs.get(name);
        if (text == null) throw refuse(requestId, ErrorCode.NO_SUCH_PROGRAM, "no program named '" + name + "'");
        List<ProgramInterpreter.Step> steps;
        try {
            steps = interpreter.compile(new String(text, StandardCharsets.UTF_8), name, robot.dof());
        } catch (IllegalArgumentException e) {
            throw refuse(requestId, ErrorCode.PROGRAM_NOT_SIMULATED, e.getMessage());
        }
        if (requestId > 0) outcomes.put(requestId, Boolean.TRUE);
        state = ControllerStatus.State.RUNNING;
        currentProgram = name;
        stopRequested = false;
        runner = new Thread(() -> runSteps(name, steps), "robopro-sim-program-" + name);
        runner.setDaemon(true);
        runner.start();
    }

    private void runSteps(String name, List<ProgramInterpreter.Step> steps) {
        ProgramInterpreter.Step current = null;
        try {
            for (ProgramInterpreter.Step step : steps) {
                if (stopRequested) break;
                current = step;
                synchronized (this) {
                    execute(step);
                }
            }
            synchronized (this) {
                state = ControllerStatus.State.IDLE;
            }
        } catch (RuntimeException e) {
            synchronized (this) {
                ErrorCode code = e instanceof CommsException.Refused r ? r.code() : ErrorCode.PROGRAM_RUNTIME;
                String msg = e instanceof CommsException.Refused r ? stripCode(r) : e.toString();
                logError(code, name + " " + (current == null ? "" : current.where()) + ": " + msg);
                state = ControllerStatus.State.ERROR;
            }
        }
    }

    /** One program step; the instruction's tool, work object and speed become the controller's. */
    private void execute(ProgramInterpreter.Step step) {
        if (step.kind() == ProgramInterpreter.Kind.WAIT) {
            clockS += step.waitS();
            return;
        }
        speed = step.speed();
        flangeTtool = step.flangeTtool();
        baseTwobj = step.baseTwobj();
        switch (step.kind()) {
            case ABS_JOINTS -> executeJointMove(step.joints(), speed, step.timeS());
            case JOINT_TO_POSE -> {
                double[] qt = robot.inverse(step.baseTflange(), q).orElseThrow(() -> new CommsException.Refused(
                        ErrorCode.UNREACHABLE, "MoveJ target out of reach"));
                executeJointMove(qt, speed, step.timeS());
            }
            case LINEAR -> executeLinear(step.baseTflange().times(flangeTtool), speed, step.timeS());
            case CIRCULAR -> executeCircular(step.baseTflangeCirc().times(flangeTtool), step.baseTflange().times(flangeTtool), speed,
                    step.timeS());
            case WAIT -> throw new AssertionError();
        }
    }

    @Override
    public void stopProgram() {
        Thread t;
        synchronized (this) {
            stopRequested = true;
            t = runner;
        }
        if (t != null && t != Thread.currentThread()) {
            try {
                t.join(10_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Waits until no program runs (tests; the CLI polls status instead). */
    public void awaitIdle(Duration max) throws InterruptedException {
        Thread t;
        synchronized (this) {
            t = runner;
        }
        if (t != null) t.join(max.toMillis());
    }

    private void logError(ErrorCode code, String msg) {
        errorCount++;
        lastError = code;
        lastErrorMessage = msg;
        LOG.info("controller error {} {}", code.wire(), msg);
    }

    /** Records an error reply (the status shows the last one). */
    public synchronized void recordError(ErrorCode code, String msg) { logError(code, msg); }

    @Override
    public synchronized ControllerStatus readStatus() {
        return new ControllerStatus(state, currentProgram, errorCount, lastError, lastErrorMessage, clockS);
    }

    // ---------------------------------------------------------------- receiver plumbing

    @Override public boolean deduplicatesRequests() { return true; }

    @Override public void setReplyTimeout(Duration timeout) { }

    @Override public void reconnect() { }

    @Override public void close() { stopProgram(); }

    @Override
    public synchronized String toString() {
        return "SimulatedController[" + robot.name() + ", q=" + Arrays.toString(Units.radToDeg(q)) + " deg]";
    }
}
