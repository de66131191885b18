package org.robopro.programs.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;
import org.robopro.programs.Move;
import org.robopro.models.SignalDescription;
import org.robopro.programs.sim.IoStep;
import org.robopro.programs.sim.MoveStep;
import org.robopro.programs.sim.Simulation;
import org.robopro.programs.sim.ProgramStep;
import org.robopro.programs.sim.WaitStep;

/**
 * Checks a program run ({@link ProgramStep}s from the interpreter) against a robot model:
 * reachability with the programmed configuration, inverse kinematics at every interpolated
 * point of MoveL and MoveC (configuration held: each point solved next to the previous one),
 * joint limits, configuration changes, closeness to singularities, and a cycle-time estimate
 * from the joint speed limits with trapezoidal velocity profiles, fly-by points blended within
 * their zones. With a {@link CheckCache}, motions whose inputs did not change since an earlier
 * check are not solved again. Thread-safe.
 */
public final class PathChecker {
    /**
     * @param stepM              interpolation step along a Cartesian path, m
     * @param stepRad            interpolation step of the tool orientation, rad
     * @param singularityWarning singularity measure (IkSolution) below which a point is "near a singularity"
     * @param rampS              time to reach full speed: acceleration = speed limit / rampS (trapezoid assumption)
     * @param maxJointJumpRad    joint change between neighbouring path points taken as a configuration change
     * @param qStart             joint values (rad) the robot starts from; empty: at the first target
     */
    public record Options(double stepM, double stepRad, double singularityWarning, double rampS, double maxJointJumpRad,
                          Optional<double[]> qStart) {
        public static final Options DEFAULT = new Options(0.005, Math.toRadians(2), 0.02, 0.25, Math.toRadians(20), Optional.empty());

        public Options withStart(double[] q) { return new Options(stepM, stepRad, singularityWarning, rampS, maxJointJumpRad, Optional.of(q.clone())); }
    }

    private final KinematicModel model;
    private final InverseKinematics ik;
    private final Options opt;
    private final double[] vMax;
    /** Upper bound on the flange's distance from the base, m (infinite when a prismatic joint has no limit). */
    private final double reach;
    /** What a motion's result depends on besides the motion and its start: the model (by identity) and the options. */
    private final List<Object> signature;

    public PathChecker(KinematicModel model, Options options) {
        this.model = model;
        this.ik = InverseKinematics.of(model);
        this.opt = options;
        int n = model.dof();
        vMax = new double[n];
        for (int i = 0; i < n; i++) {
            double v = model.description().joints().get(i).maxSpeed();
            vMax[i] = v > 0 && Double.isFinite(v) ? v : Math.toRadians(90);
        }
        reach = reach(model);
        fkWorkspace = ThreadLocal.withInitial(model::newWorkspace);
        signature = List.of(model, options.stepM(), options.stepRad(), options.singularityWarning(), options.rampS(), options.maxJointJumpRad());
    }

    /**
     * An upper bound on the flange's distance from the base over all joint values: the sum of
     * the distances between consecutive joint origins (a revolute joint turns about an axis
     * through its own origin, so the distance to the next origin does not change), plus the
     * travel of prismatic joints (triangle inequality).
     */
    static double reach(KinematicModel model) {
        Pose[] f = model.linkFrames(new double[model.dof()]);
        double r = 0;
        for (int k = 0; k + 1 < f.length; k++) r += f[k + 1].position().minus(f[k].position()).norm();
        for (int j = 0; j < model.dof(); j++)
            if (model.isPrismatic(j)) r += 2 * Math.max(Math.abs(model.qMin(j)), Math.abs(model.qMax(j)));
        return Double.isFinite(r) ? r : Double.POSITIVE_INFINITY;
    }

    /** The robot's reach bound, m (see {@link #reach(KinematicModel)}). */
    public double reach() { return reach; }

    /** A problem when the flange pose lies beyond the reach bound (no IK or path sampling is tried then). */
    private Optional<Problem> beyondReach(MoveStep m, Pose flange, String what) {
        double d = flange.position().norm();
        if (d <= reach * (1 + 1e-9) + 1e-9) return Optional.empty();
        return Optional.of(new Problem(Problem.Severity.ERROR, Problem.Kind.UNREACHABLE, m.label(), m.targetName(), m.source(),
                String.format(Locale.ROOT, "%s at %s mm (flange) is %.0f mm from the base, beyond the robot's reach of %.0f mm",
                        what, mm(flange.position()), d * 1e3, reach * 1e3)));
    }

    public PathChecker(KinematicModel model) { this(model, Options.DEFAULT); }

    /** Checks the steps in order and returns every problem found and the cycle-time estimate. */
    public CheckReport check(List<ProgramStep> steps) { return check(new Simulation(steps, List.of()), List.of()); }

    /**
     * Checks a simulation's steps in order against the robot and places its I/O on the cycle's
     * time line with the cell's {@code signals} (inputs constant, scripted or following an
     * output); the simulation's notices become NOT_SIMULATED warnings.
     */
    public CheckReport check(Simulation sim, List<SignalDescription> signals) { return check(sim, signals, null); }

    /**
     * As {@link #check(Simulation, List)}, reusing what earlier checks with the same {@code cache}
     * found for motions whose inputs did not change (see {@link CheckCache}); the report is the
     * same as without the cache. A null cache checks everything.
     */
    public CheckReport check(Simulation sim, List<SignalDescription> signals, CheckCache cache) {
        List<Problem> problems = new ArrayList<>();
        for (Simulation.Notice n : sim.notices())
            problems.add(new Problem(Problem.Severity.WARNING, Problem.Kind.NOT_SIMULATED, n.step(), "", n.source(), n.message()));
        List<ProgramStep> steps = sim.steps();
        int count = steps.size();
        // 1. Every motion checked along its path, timed as from and to a stop.
        Outcome[] outcomes = new Outcome[count];
        double[][] qBefore = new double[count][];
        double[] q = opt.qStart().map(double[]::clone).orElse(null);
        if (cache != null) cache.begin(signature, count);
        for (int i = 0; i < count; i++) {
            qBefore[i] = q;
            if (!(steps.get(i) instanceof MoveStep m)) continue;
            Outcome o = cache == null ? motion(m, q, problems) : cached(m, q, problems, cache);
            if (m.time().isPresent()) o = new Outcome(o.q, m.time().getAsDouble(), o.points, o.lengthM, o.samples);
            outcomes[i] = o;
            if (o.q != null) q = o.q;
        }
        // 2. Fly-by points: corners blended within the zone, speed kept through them.
        double[] stopDur = new double[count], blendDur = new double[count], deviation = new double[count];
        for (int i = 0; i < count; i++) if (outcomes[i] != null) stopDur[i] = blendDur[i] = outcomes[i].duration;
        for (int i = 0; i < count; i++) blend(steps, outcomes, qBefore, i, blendDur, deviation, cache);
        // 3. The time line with the blended durations (and once more with stops, for the comparison).
        IoTimeline io = new IoTimeline(signals);
        List<CheckReport.StepResult> results = new ArrayList<>();
        double total = timeLine(steps, blendDur, io, problems, qBefore, outcomes, results);
        double totalStops = timeLine(steps, stopDur, new IoTimeline(signals), new ArrayList<>(), qBefore, outcomes, null);
        for (int i = 0; i < count; i++)
            if (deviation[i] > 0) {
                CheckReport.StepResult r = results.get(i);
                results.set(i, new CheckReport.StepResult(r.step(), r.target(), r.durationS(), r.qEnd(), r.interpolationPoints(), r.samples(),
                        deviation[i]));
            }
        io.end(total);
        String assumptions = String.format(Locale.ROOT, "trapezoidal profiles reaching full speed in %.2f s, fly-by points blended "
                + "(parabolic corner within the zone, in joint space where a MoveJ takes part; speed kept), joint speed limits from the robot description", opt.rampS());
        return new CheckReport(problems, results, total, assumptions, io.events(), io.arcTime, totalStops);
    }

    private Outcome motion(MoveStep m, double[] q, List<Problem> problems) {
        return switch (m.kind()) {
            case MOVE_ABS_J -> absJ(m, q, problems);
            case MOVE_J -> joint(m, q, problems);
            case MOVE_L, MOVE_C -> cartesian(m, q, problems);
        };
    }

    /** The motion's outcome from the cache (its problems relabelled to where the motion is now), else checked and cached. */
    private Outcome cached(MoveStep m, double[] q, List<Problem> problems, CheckCache cache) {
        CheckCache.Key key = new CheckCache.Key(m, q);
        CheckCache.Entry e = cache.get(key);
        if (e == null) {
            List<Problem> own = new ArrayList<>();
            Outcome o = motion(m, q, own);
            cache.put(key, new CheckCache.Entry(o, own));
            problems.addAll(own);
            return o;
        }
        for (Problem p : e.problems())
            problems.add(new Problem(p.severity(), p.kind(), m.label(), p.target(), m.source(), p.message()));
        return e.outcome();
    }

    /** Places waits and I/O on the time line with the motions' durations {@code dur}; returns the cycle time. */
    private double timeLine(List<ProgramStep> steps, double[] dur, IoTimeline io, List<Problem> problems, double[][] qBefore,
                            Outcome[] outcomes, List<CheckReport.StepResult> results) {
        double total = 0, moveStart = 0, moveDuration = 0, moveLength = 0;
        for (int i = 0; i < steps.size(); i++) {
            ProgramStep s = steps.get(i);
            double[] qNow = qBefore[i] == null ? null : qBefore[i].clone();
            if (s instanceof WaitStep w) {
                total += w.seconds();
                if (results != null) results.add(new CheckReport.StepResult(w.label(), "", w.seconds(), qNow, 0));
            } else if (s instanceof IoStep st) {
                double d = io.step(st, total, moveStart, moveDuration, moveLength, problems);
                total += d;
                if (results != null) results.add(new CheckReport.StepResult(st.label(), "", d, qNow, 0));
            } else {
                MoveStep m = (MoveStep) s;
                Outcome o = outcomes[i];
                moveStart = total;
                moveDuration = dur[i];
                moveLength = o.lengthM;
                total += dur[i];
                if (results != null)
                    results.add(new CheckReport.StepResult(m.label(), m.targetName(), dur[i], o.q == null ? null : o.q.clone(), o.points, o.samples));
            }
        }
        return total;
    }

    /**
     * Blends the corner at motion {@code i}'s target with the next motion when the target is a
     * fly-by point (zone, no \T) and nothing between the two makes the program wait; where a joint
     * motion takes part, in joint space ({@link #jointCorner}), else in Cartesian space. The corner
     * path leaves the incoming segment at min(zone, half its length) before the target and joins
     * the outgoing one as far after it (the controller shrinks zones that overlap the same way), a
     * parabola with the target as its control point; the speed is kept through it, so neither
     * motion ramps down or up there (half a ramp saved on each side) and the corner is shorter
     * than the two legs.
     */
    private void blend(List<ProgramStep> steps, Outcome[] outcomes, double[][] qBefore, int i, double[] dur, double[] deviation,
                       CheckCache cache) {
        if (!(steps.get(i) instanceof MoveStep m) || m.zone().finep() || m.zone().pzoneTcp() <= 0 || m.time().isPresent()) return;
        int j = i + 1;
        while (j < steps.size() && steps.get(j) instanceof IoStep io
                && io.kind() != IoStep.Kind.WAIT_SIGNAL && io.kind() != IoStep.Kind.WAIT_CONDITION) j++;
        if (j >= steps.size() || !(steps.get(j) instanceof MoveStep n) || n.time().isPresent()) return;
        Outcome a = outcomes[i], b = outcomes[j];
        if (a == null || b == null || a.q == null || b.q == null || qBefore[i] == null) return;
        Vec3 p0 = model.flange(qBefore[i]).times(m.flangeTtcp()).position();
        Vec3 p1 = model.flange(a.q).times(m.flangeTtcp()).position();
        Vec3 p2 = model.flange(b.q).times(n.flangeTtcp()).position();
        double lin = p1.minus(p0).norm(), lout = p2.minus(p1).norm();
        if (lin < 1e-9 || lout < 1e-9) return;
        double din = Math.min(m.zone().pzoneTcp(), lin / 2), dout = Math.min(m.zone().pzoneTcp(), lout / 2);
        if (isJoint(m) || isJoint(n)) {
            // Joint corners cost some hundred FKs: kept in the cache, keyed by the two motions' outcomes (the very objects a cached check reuses).
            CheckCache.CornerKey key = cache == null ? null : new CheckCache.CornerKey(a, b, qBefore[i], m, n);
            double[] c = key == null ? null : cache.corner(key);
            if (c == null) {
                c = jointCorner(m, n, qBefore[i], a, b, p1, din, dout);
                if (key != null) cache.putCorner(key, c);
            }
            deviation[i] = c[0];
            dur[i] = Math.max(0, dur[i] - rampSaving(outcomes[i].duration) - c[1] / 2);
            dur[j] = Math.max(0, dur[j] - rampSaving(outcomes[j].duration) - c[1] / 2);
            return;
        }
        Vec3 entry = p1.minus(p1.minus(p0).times(din / lin)), exit = p1.plus(p2.minus(p1).times(dout / lout));
        // Quadratic Bezier entry -> (p1) -> exit: its point nearest p1 is at t = 1/2 for equal arms.
        deviation[i] = entry.minus(p1).times(0.25).plus(exit.minus(p1).times(0.25)).norm();
        double corner = 0;
        Vec3 prev = entry;
        for (int k = 1; k <= 32; k++) {
            double t = k / 32.0;
            Vec3 pt = entry.times((1 - t) * (1 - t)).plus(p1.times(2 * t * (1 - t))).plus(exit.times(t * t));
            corner += pt.minus(prev).norm();
            prev = pt;
        }
        double v = Math.max(1e-9, Math.min(m.speed().vTcp(), n.speed().vTcp()));
        double shorter = Math.max(0, din + dout - corner) / v;
        dur[i] = Math.max(0, dur[i] - rampSaving(outcomes[i].duration) - shorter / 2);
        dur[j] = Math.max(0, dur[j] - rampSaving(outcomes[j].duration) - shorter / 2);
    }

    private static boolean isJoint(MoveStep m) { return m.kind() == Move.Kind.MOVE_J || m.kind() == Move.Kind.MOVE_ABS_J; }

    /**
     * A corner where a joint motion (MoveJ, MoveAbsJ) meets another motion, blended in joint space
     * as the controller does: the transition starts where the TCP enters the zone on the incoming
     * motion (last at {@code din} from the target, found along the motion's own joint path) and
     * ends where it leaves the zone on the outgoing one; between the two the joints follow a
     * quadratic Bezier with the target's joints as control point. The deviation is the closest
     * the blended TCP comes to the target (forward kinematics along the Bezier); the time saved is
     * half a ramp on each side, plus the difference between the legs' and the corner's joint-space
     * travel at full joint speed (the slowest axis's time, the measure a joint motion is timed by).
     * Returns {deviation m, joint-travel time saved s}; the caller adds the ramps.
     */
    private double[] jointCorner(MoveStep m, MoveStep n, double[] q0, Outcome a, Outcome b, Vec3 p1, double din, double dout) {
        double sIn = zoneEdge(m, q0, a, p1, din, true), sOut = zoneEdge(n, a.q, b, p1, dout, false);
        double[] qIn = along(m, q0, a, sIn), qOut = along(n, a.q, b, sOut), qc = a.q;
        double legs = 0, corner = 0, closest = tcpDistance(qIn, m, p1), tClosest = 0;
        double[] prevIn = qIn, prevOut = a.q, prevC = qIn;
        for (int k = 1; k <= 16; k++) {
            double t = k / 16.0;
            double[] li = along(m, q0, a, sIn + (1 - sIn) * t), lo = along(n, a.q, b, sOut * t);
            legs += jointTravel(prevIn, li) + jointTravel(prevOut, lo);
            prevIn = li;
            prevOut = lo;
            double[] qb = bezier(qIn, qc, qOut, t);
            corner += jointTravel(prevC, qb);
            prevC = qb;
            double d = tcpDistance(qb, m, p1);
            if (d < closest) { closest = d; tClosest = t; }
        }
        // The closest point between the samples next to the best one (golden-section search).
        double lo = Math.max(0, tClosest - 1 / 16.0), hi = Math.min(1, tClosest + 1 / 16.0), g = (Math.sqrt(5) - 1) / 2;
        for (int it = 0; it < 24; it++) {
            double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            double d1 = tcpDistance(bezier(qIn, qc, qOut, x1), m, p1), d2 = tcpDistance(bezier(qIn, qc, qOut, x2), m, p1);
            closest = Math.min(closest, Math.min(d1, d2));
            if (d1 < d2) hi = x2; else lo = x1;
        }
        return new double[] {closest, Math.max(0, legs - corner)};
    }

    private static double[] bezier(double[] a, double[] c, double[] b, double t) {
        double[] q = new double[a.length];
        for (int d = 0; d < q.length; d++) q[d] = (1 - t) * (1 - t) * a[d] + 2 * t * (1 - t) * c[d] + t * t * b[d];
        return q;
    }

    /**
     * Where motion m (from q0) crosses the zone's edge, {@code r} from the target p1 (fraction of
     * the motion): entering the zone for the last time on an incoming motion, leaving it for the
     * first time on an outgoing one. A scan of 16 steps from the target's end, then bisection.
     */
    private double zoneEdge(MoveStep m, double[] q0, Outcome o, Vec3 p1, double r, boolean incoming) {
        double inside = incoming ? 1 : 0, outside = incoming ? 0 : 1;
        boolean found = false;
        for (int k = 1; k <= 16; k++) {
            double s = incoming ? 1 - k / 16.0 : k / 16.0;
            if (tcpDistance(along(m, q0, o, s), m, p1) >= r) { outside = s; found = true; break; }
            inside = s;
        }
        if (!found) return outside;
        for (int it = 0; it < 10; it++) {
            double mid = (inside + outside) / 2;
            if (tcpDistance(along(m, q0, o, mid), m, p1) >= r) outside = mid; else inside = mid;
        }
        return outside;
    }

    /** Joint values at fraction s of motion m from q0 (its checked samples for MoveL/MoveC, straight in joint space otherwise). */
    private static double[] along(MoveStep m, double[] q0, Outcome o, double s) {
        List<double[]> path = o.samples;
        double[] a, b;
        double f;
        if (isJoint(m) || path.isEmpty()) {
            a = q0;
            b = o.q;
            f = s;
        } else {
            double x = s * path.size();
            int k = Math.min(path.size() - 1, (int) Math.floor(x));
            a = k == 0 ? q0 : path.get(k - 1);
            b = path.get(k);
            f = Math.min(1, x - k);
        }
        double[] q = new double[a.length];
        for (int d = 0; d < q.length; d++) q[d] = a[d] + f * (b[d] - a[d]);
        return q;
    }

    /** Forward-kinematics buffers of the calling thread (the corner searches run thousands of FKs per check). */
    private final ThreadLocal<KinematicModel.Workspace> fkWorkspace;
    private final ThreadLocal<double[]> fkOut = ThreadLocal.withInitial(() -> new double[12]);

    /** Distance of motion m's TCP at joints q from point p, without allocating. */
    private double tcpDistance(double[] q, MoveStep m, Vec3 p) {
        KinematicModel.Workspace ws = fkWorkspace.get();
        double[] f = fkOut.get();
        model.flange(q, ws, f);
        Vec3 t = m.flangeTtcp().position();
        double x = f[0] * t.x() + f[1] * t.y() + f[2] * t.z() + f[3] - p.x();
        double y = f[4] * t.x() + f[5] * t.y() + f[6] * t.z() + f[7] - p.y();
        double z = f[8] * t.x() + f[9] * t.y() + f[10] * t.z() + f[11] - p.z();
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** Time at full joint speed from a to b: the slowest axis's. */
    private double jointTravel(double[] a, double[] b) {
        double t = 0;
        for (int d = 0; d < a.length; d++) t = Math.max(t, Math.abs(b[d] - a[d]) / vMax[d]);
        return t;
    }

    /**
     * Time saved by not stopping at one end of a motion of stop-to-stop duration {@code d}: half a
     * ramp when full speed is reached (d >= 2 rampS), else the triangle's share (one-sided
     * acceleration over the same distance takes d / sqrt 2).
     */
    private double rampSaving(double d) {
        return d >= 2 * opt.rampS() ? opt.rampS() / 2 : d * (1 - 1 / Math.sqrt(2)) / 2;
    }

    /**
     * The I/O state over the cycle's time: what the program set (with delays and pulses),
     * triggers placed along their motion, inputs from the cell's table (constant, scripted, or
     * following an output after a delay), and the welding arc.
     */
    private static final class IoTimeline {
        final Map<String, SignalDescription> table = new HashMap<>();
        /** Changes by lower-case signal: {time, value}, in the order they were made. */
        final Map<String, List<double[]>> changes = new HashMap<>();
        final List<CheckReport.IoEvent> events = new ArrayList<>();
        double arcOnAt = Double.NaN, arcTime;

        IoTimeline(List<SignalDescription> signals) {
            for (SignalDescription d : signals) {
                table.put(d.key(), d);
                for (SignalDescription.Change c : d.script()) changes.computeIfAbsent(d.key(), k -> new ArrayList<>()).add(new double[] {c.timeS(), c.value()});
            }
        }

        void set(String signal, double t, double v, IoStep s) {
            String key = signal.toLowerCase(Locale.ROOT);
            changes.computeIfAbsent(key, k -> new ArrayList<>()).add(new double[] {t, v});
            events.add(new CheckReport.IoEvent(t, signal, v, s.label(), s.source()));
            for (SignalDescription d : table.values())
                if (d.follows().equalsIgnoreCase(signal)) set(d.name(), t + d.delayS(), v, s);
        }

        double valueAt(String key, double t) {
            SignalDescription d = table.get(key);
            double v = d == null ? 0 : d.value(), at = Double.NEGATIVE_INFINITY;
            for (double[] c : changes.getOrDefault(key, List.of()))
                if (c[0] <= t && c[0] >= at) { at = c[0]; v = c[1]; }
            return v;
        }

        /** The first time from {@code t} on when the signal has value {@code v}; NaN when never. */
        double firstTime(String key, double t, double v) {
            if (valueAt(key, t) == v) return t;
            double best = Double.NaN;
            for (double[] c : changes.getOrDefault(key, List.of()))
                if (c[0] > t && (Double.isNaN(best) || c[0] < best) && valueAt(key, c[0]) == v) best = c[0];
            return best;
        }

        /** Places one I/O step at time {@code t}; returns how long the program waits there, s. */
        double step(IoStep s, double t, double moveStart, double moveDuration, double moveLength, List<Problem> problems) {
            switch (s.kind()) {
                case SET -> set(s.signal(), t + s.seconds(), s.value(), s);
                case PULSE -> {
                    set(s.signal(), t, 1, s);
                    set(s.signal(), t + s.seconds(), 0, s);
                }
                case TRIGGER -> {
                    IoStep.Trigger tr = s.trigger().orElseThrow();
                    double end = moveStart + moveDuration;
                    double dt = tr.time() ? s.seconds()
                            : moveLength > 0 ? moveDuration * Math.min(1, s.seconds() / moveLength) : 0;
                    double at = tr.fromStart() ? moveStart + Math.min(dt, moveDuration) : Math.max(moveStart, end - dt);
                    set(s.signal(), at, s.value(), s);
                }
                case WAIT_SIGNAL -> {
                    String key = s.signal().toLowerCase(Locale.ROOT);
                    double when = firstTime(key, t, s.value());
                    String v = s.value() == 1 ? "1" : s.value() == 0 ? "0" : String.valueOf(s.value());
                    if (Double.isNaN(when)) {
                        problems.add(new Problem(Problem.Severity.WARNING, Problem.Kind.IO_WAIT, s.label(), "", s.source(),
                                s.instruction() + " waits for " + s.signal() + " = " + v + ", but nothing sets it (the program does not, the cell's "
                                        + "signal table neither scripts it nor has it follow an output): on the controller this waits "
                                        + (Double.isFinite(s.seconds()) ? "until \\MaxTime (" + s.seconds() + " s) raises ERR_WAIT_MAXTIME" : "forever")
                                        + "; counted as " + (Double.isFinite(s.seconds()) ? s.seconds() : 0) + " s"));
                        return Double.isFinite(s.seconds()) ? s.seconds() : 0;
                    }
                    double wait = when - t;
                    if (wait > s.seconds()) {
                        problems.add(new Problem(Problem.Severity.WARNING, Problem.Kind.IO_WAIT, s.label(), "", s.source(),
                                String.format(Locale.ROOT, "%s = %s arrives after %.3f s, later than \\MaxTime %.3f s (ERR_WAIT_MAXTIME)",
                                        s.signal(), v, wait, s.seconds())));
                        return s.seconds();
                    }
                    return wait;
                }
                case WAIT_CONDITION -> problems.add(new Problem(Problem.Severity.WARNING, Problem.Kind.IO_WAIT, s.label(), "", s.source(),
                        "WaitUntil " + s.text() + " is false and nothing in the simulation changes it: assumed true at once"));
                case ARC_ON -> {
                    if (Double.isNaN(arcOnAt)) arcOnAt = t;
                    events.add(new CheckReport.IoEvent(t, "arc", 1, s.label(), s.source()));
                }
                case ARC_OFF -> {
                    if (!Double.isNaN(arcOnAt)) arcTime += t - arcOnAt;
                    arcOnAt = Double.NaN;
                    events.add(new CheckReport.IoEvent(t, "arc", 0, s.label(), s.source()));
                }
            }
            return 0;
        }

        void end(double t) {
            if (!Double.isNaN(arcOnAt)) arcTime += t - arcOnAt;
        }

        List<CheckReport.IoEvent> events() {
            List<CheckReport.IoEvent> out = new ArrayList<>(events);
            out.sort(java.util.Comparator.comparingDouble(CheckReport.IoEvent::timeS));
            return out;
        }
    }

    /** One motion checked from a start: end joints, stop-to-stop duration, points, TCP path length, joint values along the path. */
    record Outcome(double[] q, double duration, int points, double lengthM, List<double[]> samples) {
        Outcome {
            samples = List.copyOf(samples); // immutable, so reports made from a cached outcome share it
        }

        Outcome(double[] q, double duration, int points) { this(q, duration, points, 0, List.of()); }

        Outcome(double[] q, double duration, int points, double lengthM) { this(q, duration, points, lengthM, List.of()); }
    }

    private Outcome absJ(MoveStep m, double[] q, List<Problem> problems) {
        double[] all = m.q().orElseThrow();
        double[] target = Arrays.copyOf(all, model.dof());
        if (!model.withinLimits(target)) problems.add(limitProblem(m, target));
        checkSingularity(m, target, problems);
        return new Outcome(target, q == null ? 0 : jointTime(q, target, m), 1);
    }

    private Outcome joint(MoveStep m, double[] q, List<Problem> problems) {
        Pose flange = m.baseTflange().orElseThrow();
        ConfData conf = m.conf().orElseThrow();
        Optional<Problem> far = beyondReach(m, flange, "the target");
        if (far.isPresent()) {
            problems.add(far.get());
            return new Outcome(null, 0, 1);
        }
        Optional<IkSolution> s = ik.solveWithConf(flange, conf);
        if (s.isEmpty()) {
            problems.add(unreachable(m, flange, conf));
            return new Outcome(null, 0, 1);
        }
        double[] target = s.get().q();
        checkSingularity(m, target, problems);
        Pose from = q == null ? null : model.flange(q).times(m.flangeTtcp());
        double t = q == null ? 0 : Math.max(jointTime(q, target, m), cartesianTime(from, m.baseTtcp().get(), 0, m));
        return new Outcome(target, t, 1, from == null ? 0 : from.distanceTo(m.baseTtcp().get()));
    }

    private Outcome cartesian(MoveStep m, double[] q, List<Problem> problems) {
        Pose flangeEnd = m.baseTflange().orElseThrow();
        ConfData conf = m.conf().orElseThrow();
        // Far targets are refused before sampling: the path's length (and so the number of
        // interpolated points) is then bounded by the reach.
        Optional<Problem> far = beyondReach(m, flangeEnd, "the target");
        if (far.isEmpty() && m.baseTflangeCirc().isPresent()) far = beyondReach(m, m.baseTflangeCirc().get(), "the circle point");
        if (far.isPresent()) {
            problems.add(far.get());
            return new Outcome(null, 0, 1);
        }
        if (q == null) { // no start: the robot is put at the target
            Optional<IkSolution> s = ik.solveWithConf(flangeEnd, conf);
            if (s.isEmpty()) {
                problems.add(unreachable(m, flangeEnd, conf));
                return new Outcome(null, 0, 1);
            }
            return new Outcome(s.get().q(), 0, 1);
        }
        Pose tcpStart = model.flange(q).times(m.flangeTtcp());
        Pose tcpEnd = m.baseTtcp().orElseThrow();
        Pose tcpCirc = m.baseTtcpCirc().orElse(null);
        Pose toolInv = m.flangeTtcp().inverse();
        Circle circle = null;
        double length;
        if (m.kind() == Move.Kind.MOVE_C) {
            circle = Circle.through(tcpStart.position(), tcpCirc.position(), tcpEnd.position());
            if (circle == null) {
                problems.add(new Problem(Problem.Severity.ERROR, Problem.Kind.BAD_CIRCLE, m.label(), m.targetName(), m.source(),
                        "start, circle point " + m.circName().orElse("?") + " and end do not define a circle (coincident or collinear)"));
                return new Outcome(null, 0, 1);
            }
            length = circle.length();
        } else {
            length = tcpStart.distanceTo(tcpEnd);
        }
        Vec3 w = tcpStart.inverse().times(tcpEnd).rotationVector();
        double angle = w.norm();
        int n = Math.max(1, (int) Math.ceil(Math.max(length / opt.stepM(), angle / opt.stepRad())));
        double[] prev = q.clone();
        List<double[]> samples = new ArrayList<>(Math.min(n, 4096));
        double jointLimitedTime = 0;
        boolean reported = false, limitReported = false, singReported = false, jumpReported = false;
        for (int k = 1; k <= n; k++) {
            double s = (double) k / n;
            Vec3 p = circle != null ? circle.at(s) : tcpStart.position().plus(tcpEnd.position().minus(tcpStart.position()).times(s));
            Pose rot = angle > 1e-12 ? Pose.rotAxis(w, angle * s) : Pose.IDENTITY;
            Pose ori = tcpStart.times(rot);
            Pose tcp = Pose.of(ori.rotationRowMajor(), p.x(), p.y(), p.z());
            // The last point is the target itself (not start + whole step, which rounds differently
            // for each start): the motion then ends where it ends whatever came before it.
            Optional<IkSolution> sol = ik.solveNear(k == n ? flangeEnd : tcp.times(toolInv), prev);
            if (sol.isEmpty()) {
                if (!reported)
                    problems.add(new Problem(Problem.Severity.ERROR, Problem.Kind.UNREACHABLE, m.label(), m.targetName(), m.source(),
                            String.format(Locale.ROOT, "path point %d of %d (%.0f%% along, at %s mm) is out of reach", k, n, 100 * s, mm(p))));
                reported = true;
                break;
            }
            double[] qk = sol.get().q();
            double dt = 0, jump = 0;
            for (int j = 0; j < qk.length; j++) {
                double d = Math.abs(qk[j] - prev[j]);
                dt = Math.max(dt, d / vMax[j]);
                jump = Math.max(jump, d);
            }
            jointLimitedTime += dt;
            if (!sol.get().withinLimits() && !limitReported) {
                problems.add(limitProblem(m, qk));
                limitReported = true;
            }
            if (jump > opt.maxJointJumpRad() && !jumpReported) {
                problems.add(new Problem(Problem.Severity.ERROR, Problem.Kind.CONFIGURATION_CHANGE, m.label(), m.targetName(), m.source(),
                        String.format(Locale.ROOT, "joints jump %.1f deg between path points %d and %d: the configuration cannot be held", Math.toDegrees(jump), k - 1, k)));
                jumpReported = true;
            }
            if (sol.get().singularityMeasure() < opt.singularityWarning() && !singReported) {
                problems.add(singular(m, sol.get().singularityMeasure(), String.format(Locale.ROOT, "at path point %d of %d", k, n)));
                singReported = true;
            }
            prev = qk;
            samples.add(qk);
        }
        if (reported) return new Outcome(null, 0, n);
        ConfData reached = ik.confOf(prev);
        if (!ik.inConfiguration(prev, conf)) // a joint on a quadrant boundary is in both quadrants
            problems.add(new Problem(reached.cfx() != conf.cfx() ? Problem.Severity.ERROR : Problem.Severity.WARNING,
                    Problem.Kind.CONFIGURATION_MISMATCH, m.label(), m.targetName(), m.source(),
                    "the path ends in configuration " + confText(reached) + ", the target asks for " + confText(conf)));
        double t = Math.max(cartesianTime(tcpStart, tcpEnd, length, m), jointLimitedTime + opt.rampS());
        return new Outcome(prev, t, n, length, samples);
    }

    /** Trapezoid time of the TCP path (length m, or the straight distance when 0) and of the reorientation. */
    private double cartesianTime(Pose from, Pose to, double length, MoveStep m) {
        double l = length > 0 ? length : from.distanceTo(to);
        double a = from.angleTo(to);
        return Math.max(trapezoid(l, m.speed().vTcp()), trapezoid(a, m.speed().vOri()));
    }

    private double jointTime(double[] from, double[] to, MoveStep m) {
        double t = 0;
        for (int j = 0; j < from.length; j++) t = Math.max(t, trapezoid(Math.abs(to[j] - from[j]), vMax[j]));
        return t;
    }

    /** Time to cover d with speed limit v and acceleration v / rampS, starting and ending at rest. */
    double trapezoid(double d, double v) {
        if (d <= 0) return 0;
        if (!(v > 0)) return Double.POSITIVE_INFINITY;
        double a = v / opt.rampS();
        if (d >= v * v / a) return d / v + v / a;
        return 2 * Math.sqrt(d / a);
    }

    private void checkSingularity(MoveStep m, double[] q, List<Problem> problems) {
        double s = ik.singularityMeasure(q);
        if (s < opt.singularityWarning()) problems.add(singular(m, s, "at the target"));
    }

    private Problem singular(MoveStep m, double measure, String where) {
        return new Problem(Problem.Severity.WARNING, Problem.Kind.NEAR_SINGULARITY, m.label(), m.targetName(), m.source(),
                String.format(Locale.ROOT, "near a singularity %s (measure %.4f < %.4f)", where, measure, opt.singularityWarning()));
    }

    private Problem limitProblem(MoveStep m, double[] q) {
        StringBuilder b = new StringBuilder();
        for (int j = 0; j < q.length; j++)
            if (q[j] < model.qMin(j) || q[j] > model.qMax(j))
                b.append(String.format(Locale.ROOT, " axis %d at %.2f deg outside [%.1f, %.1f];", j + 1, Math.toDegrees(q[j]),
                        Math.toDegrees(model.qMin(j)), Math.toDegrees(model.qMax(j))));
        return new Problem(Problem.Severity.ERROR, Problem.Kind.JOINT_LIMIT, m.label(), m.targetName(), m.source(), "joint limit:" + b);
    }

    private Problem unreachable(MoveStep m, Pose flange, ConfData conf) {
        List<IkSolution> all = ik.solveAll(flange);
        String msg;
        if (all.isEmpty()) msg = "no joint values reach the target at " + mm(flange.position()) + " mm (flange)";
        else {
            List<String> confs = all.stream().filter(IkSolution::withinLimits).map(s -> confText(s.conf())).distinct().toList();
            msg = confs.isEmpty() ? "the target is reachable only outside the joint limits"
                    : "configuration " + confText(conf) + " does not reach the target; reachable with " + String.join(", ", confs);
        }
        return new Problem(Problem.Severity.ERROR, Problem.Kind.UNREACHABLE, m.label(), m.targetName(), m.source(), msg);
    }

    static String confText(ConfData c) { return "[" + c.cf1() + "," + c.cf4() + "," + c.cf6() + "," + c.cfx() + "]"; }

    private static String mm(Vec3 p) {
        return String.format(Locale.ROOT, "(%.1f, %.1f, %.1f)", p.x() * 1e3, p.y() * 1e3, p.z() * 1e3);
    }

    /**
     * The circular arc of a MoveC, from a through b to c: the one place robopro computes it (path
     * checks here, the workbench's sampling and drawing).
     */
    public static final class Circle {
        final Vec3 center, u, n;
        final double radius, angle;

        private Circle(Vec3 center, Vec3 u, Vec3 n, double radius, double angle) {
            this.center = center; this.u = u; this.n = n; this.radius = radius; this.angle = angle;
        }

        /** The circle through three points, or null when they are (nearly) collinear or coincident. */
        public static Circle through(Vec3 a, Vec3 b, Vec3 c) {
            Vec3 ac = a.minus(c), bc = b.minus(c);
            Vec3 cr = ac.cross(bc);
            double cr2 = cr.dot(cr);
            double scale = Math.max(ac.norm(), bc.norm());
            if (!(scale > 1e-9) || Math.sqrt(cr2) < 1e-6 * scale * scale) return null;
            Vec3 center = c.plus(bc.times(ac.dot(ac)).minus(ac.times(bc.dot(bc))).cross(cr).times(1 / (2 * cr2)));
            Vec3 n = b.minus(a).cross(c.minus(b)).normalized(); // travel a -> b -> c turns positively about n
            Vec3 u = a.minus(center);
            Vec3 v = c.minus(center);
            double ang = Math.atan2(u.cross(v).dot(n), u.dot(v));
            if (ang <= 0) ang += 2 * Math.PI;
            return new Circle(center, u, n, u.norm(), ang);
        }

        /** The point at fraction {@code s} (0 = a, 1 = c) of the arc. */
        public Vec3 at(double s) { return center.plus(Pose.rotAxis(n, angle * s).rotate(u)); }

        public Vec3 center() { return center; }

        /** Radius, m. */
        public double radius() { return radius; }

        /** Arc length from a to c, m. */
        public double length() { return radius * angle; }
    }
}
