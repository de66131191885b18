package org.robopro.app.workbench.model;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;
import org.robopro.programs.RapidModule;
import org.robopro.programs.check.CheckCache;
import org.robopro.programs.check.CheckReport;
import org.robopro.programs.check.PathChecker;
import org.robopro.programs.check.Problem;
import org.robopro.programs.collision.ClearanceChecker;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;
import org.robopro.programs.sim.ProgramStep;
import org.robopro.programs.sim.Simulation;

/**
 * The workbench program run through the programs module: mapped to RAPID
 * ({@link ProgramModule}), stepped by the {@link MotionInterpreter}, checked by the
 * {@link PathChecker} (reachability at interpolated points, limits, configuration, singularity,
 * cycle time), with the problems grouped by instruction and target, and a timeline of joint
 * values for playback built from the checker's per-step durations and end joints (MoveJ in
 * joint space, MoveL on the TCP line and MoveC on the TCP circle with IK next to the previous
 * sample, as the checker does). Immutable.
 */
public final class ProgramRun {
    /** The outcome for one instruction: its problems (errors and warnings) and duration. */
    public record Step(int index, Instruction instruction, String label, List<Problem> problems, double seconds) {
        public Step { problems = List.copyOf(problems); }

        /** No errors (warnings allowed). */
        public boolean ok() { return problems.stream().noneMatch(p -> p.severity() == Problem.Severity.ERROR); }

        /** The first error's message, else the first warning's, else the duration. */
        public String message() {
            for (Problem.Severity s : Problem.Severity.values())
                for (Problem p : problems) if (p.severity() == s) return p.kind().name().toLowerCase(Locale.ROOT) + ": " + p.message();
            return String.format(Locale.ROOT, "%.2f s", seconds);
        }
    }

    private final List<Instruction> program;
    private final RapidModule module;
    private final CheckReport report;
    private final List<Step> steps;
    private final Set<String> badTargets;
    private final double[] times;
    private final double[][] qs;
    private final Vec3[] tcpWorld;

    private ProgramRun(List<Instruction> program, RapidModule module, CheckReport report, List<Step> steps, Set<String> badTargets, double[] times,
                       double[][] qs, Vec3[] tcpWorld) {
        this.program = List.copyOf(program);
        this.module = module;
        this.report = report;
        this.steps = List.copyOf(steps);
        this.badTargets = Set.copyOf(badTargets);
        this.times = times;
        this.qs = qs;
        this.tcpWorld = tcpWorld;
    }

    /** The program this run checked (the model's at the time; results are shown only beside this program). */
    public List<Instruction> program() { return program; }
    public RapidModule module() { return module; }
    /** The path checker's report; null when the robot has no kinematics-module model. */
    public CheckReport report() { return report; }
    public List<Step> steps() { return steps; }
    public boolean ok() { return steps.stream().allMatch(Step::ok); }

    /**
     * The outcome of program line {@code index} as one step: a motion's own step, or for a kept
     * statement (a call, a loop) the motions it ran merged (every problem, the durations added);
     * empty for a line that moved nothing (a wait, I/O, a comment).
     */
    public Optional<Step> line(int index) {
        List<Step> of = steps.stream().filter(s -> s.index() == index).toList();
        if (of.size() <= 1) return of.stream().findFirst();
        List<Problem> problems = new ArrayList<>();
        double seconds = 0;
        for (Step s : of) {
            problems.addAll(s.problems());
            seconds += s.seconds();
        }
        return Optional.of(new Step(index, of.get(0).instruction(), of.get(0).label(), problems, seconds));
    }
    /** Targets named by an error (drawn red). */
    public Set<String> badTargets() { return badTargets; }
    public int sampleCount() { return times.length; }
    public double duration() { return times.length == 0 ? 0 : times[times.length - 1]; }
    public Vec3 tcp(int i) { return tcpWorld[i]; }
    public double[] qAt(int i) { return qs[i].clone(); }

    /** Joint values at time t (s), linearly interpolated between samples. */
    public double[] qAtTime(double t) {
        if (times.length == 0) throw new IllegalStateException("empty program run");
        if (t <= times[0]) return qs[0].clone();
        int lo = 0, hi = times.length - 1;
        if (t >= times[hi]) return qs[hi].clone();
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (times[mid] <= t) lo = mid; else hi = mid;
        }
        double s = (t - times[lo]) / Math.max(1e-12, times[hi] - times[lo]);
        double[] a = qs[lo], b = qs[hi], out = new double[a.length];
        for (int k = 0; k < a.length; k++) out[k] = a[k] + s * (b[k] - a[k]);
        return out;
    }

    /** Maps, steps, checks and samples the model's program. */
    public static ProgramRun of(WorkbenchModel m) { return of(m, null, null); }

    /**
     * As {@link #of(WorkbenchModel)}, reusing the path check's results for unchanged motions from
     * {@code cache} (null: none) and sweeping every move for collisions with {@code clearance}
     * (null: no collision check); its problems join the path check's on each instruction.
     */
    public static ProgramRun of(WorkbenchModel m, CheckCache cache, ClearanceChecker clearance) {
        List<Instruction> program = m.program();
        RobotKinematics k = m.kinematics();
        List<Step> out = new ArrayList<>();
        Set<String> bad = new HashSet<>();
        // Instructions naming missing targets cannot be mapped: report them, run the rest.
        List<Instruction> runnable = new ArrayList<>();
        List<Integer> index = new ArrayList<>();
        for (int i = 0; i < program.size(); i++) {
            Instruction ins = program.get(i);
            if (!ins.type().motion()) continue; // a statement kept from an imported module: not run here
            String missing = m.target(ins.target()).isEmpty() ? ins.target()
                    : ins.via() != null && m.target(ins.via()).isEmpty() ? ins.via() : null;
            if (missing != null) {
                out.add(new Step(i, ins, "main#? " + ins.type().rapid() + " " + ins.target(), List.of(new Problem(Problem.Severity.ERROR,
                        Problem.Kind.UNREACHABLE, "instruction " + (i + 1), missing, Optional.empty(), "no target named " + missing)), 0));
                continue;
            }
            runnable.add(ins);
            index.add(i);
        }
        RapidModule module = ProgramModule.toRapid(m, runnable, "Workbench");
        Optional<ProgramModule.Source> src = m.programSource();
        // An imported program runs as the whole module with the edits spliced in: motions in
        // called routines and loops are checked and drawn too, waits counted in the cycle time.
        List<Instruction> lines = runnable;
        if (src.isPresent()) {
            lines = new ArrayList<>();
            index.clear();
            for (int i = 0; i < program.size(); i++)
                if (!program.get(i).type().motion() || runnable.contains(program.get(i))) { lines.add(program.get(i)); index.add(i); }
            module = ProgramModule.spliced(src.get(), module, lines, "Workbench");
        }
        String entry = src.map(ProgramModule.Source::entry).orElse("main");
        List<ProgramStep> steps = lines.isEmpty() ? List.of() : MotionInterpreter.of(module).run(entry);
        Optional<KinematicModel> km = k.kinematicModel();
        CheckReport report = km.isPresent() && !steps.isEmpty() ? new PathChecker(km.get()).check(new Simulation(steps, List.of()), List.of(), cache) : null;
        List<Problem> collisions = clearance == null || report == null ? List.of() : clearance.check(steps, report, Optional.empty()).problems();
        List<double[]> qEnd = new ArrayList<>();
        for (int s = 0; s < steps.size(); s++) {
            if (!(steps.get(s) instanceof MoveStep mv)) { qEnd.add(null); continue; } // a wait or I/O: no motion
            int line = src.isPresent() ? line(mv, entry) : s;
            List<Problem> ps = new ArrayList<>();
            double dur = 0;
            double[] q = null;
            if (report != null) {
                for (Problem p : report.problems()) if (p.step().equals(mv.label())) ps.add(p);
                for (Problem p : collisions) if (p.step().equals(mv.label())) ps.add(p);
                dur = report.steps().get(s).durationS();
                q = report.steps().get(s).qEnd();
            } else {
                Optional<double[]> sol = k.solveNear(mv.baseTflange().orElseThrow(), m.target(mv.targetName()).map(Target::qTaught).orElse(m.q()));
                if (sol.isEmpty()) ps.add(new Problem(Problem.Severity.ERROR, Problem.Kind.UNREACHABLE, mv.label(), mv.targetName(),
                        Optional.empty(), "out of reach"));
                q = sol.orElse(null);
            }
            for (Problem p : ps) if (p.severity() == Problem.Severity.ERROR) bad.add(p.target());
            if (line >= 0 && line < lines.size()) out.add(new Step(index.get(line), lines.get(line), mv.label(), ps, dur));
            qEnd.add(q);
        }
        out.sort((a, b) -> Integer.compare(a.index(), b.index()));
        for (Step st : out) if (!st.ok() && st.label().startsWith("main#?")) bad.add(st.problems().get(0).target());
        return sample(m, program, module, report, out, bad, steps, qEnd);
    }

    /**
     * The line of the entry procedure a motion belongs to: its own statement at the top level,
     * else the call or loop of the entry it ran in (the first element of its context,
     * "main#4[i=2] > weld#3"); -1 when neither.
     */
    private static int line(MoveStep mv, String entry) {
        String ctx = mv.context();
        if (ctx.isEmpty()) return mv.procedure().equalsIgnoreCase(entry) ? mv.statementIndex() : -1;
        String first = ctx.split(" > ", 2)[0];
        int h = first.indexOf('#'), e = h + 1;
        if (h < 0 || !first.substring(0, h).equalsIgnoreCase(entry)) return -1;
        while (e < first.length() && Character.isDigit(first.charAt(e))) e++;
        return e > h + 1 ? Integer.parseInt(first.substring(h + 1, e)) - 1 : -1;
    }

    private static ProgramRun sample(WorkbenchModel m, List<Instruction> program, RapidModule module, CheckReport report, List<Step> out, Set<String> bad,
                                     List<ProgramStep> steps, List<double[]> qEnd) {
        RobotKinematics k = m.kinematics();
        Pose worldTbase = m.worldTbase();
        Pose flangeTtcp = m.tool().flangeTtcp();
        List<Double> times = new ArrayList<>();
        List<double[]> qs = new ArrayList<>();
        double t = 0;
        double[] q = null;
        for (int s = 0; s < steps.size(); s++) {
            double[] qe = qEnd.get(s);
            if (qe == null) continue; // failed motion: the robot stays where it was
            double dur = report == null ? 1.0 : report.steps().get(s).durationS();
            if (q == null) {
                times.add(t);
                qs.add(qe.clone());
                q = qe;
                t += dur;
                continue;
            }
            // MoveL/MoveC: the joint values the checker solved along the path (one sampler for check and playback).
            List<double[]> seg = report != null && !report.steps().get(s).samples().isEmpty()
                    ? new ArrayList<>(report.steps().get(s).samples()) : null;
            if (seg == null) {
                seg = new ArrayList<>();
                int n = 24;
                for (int i = 1; i <= n; i++) {
                    double[] qi = new double[q.length];
                    for (int j = 0; j < qi.length; j++) qi[j] = q[j] + (qe[j] - q[j]) * i / n;
                    seg.add(qi);
                }
            }
            double d = Math.max(dur, 1e-3);
            for (int i = 0; i < seg.size(); i++) {
                times.add(t + d * (i + 1) / seg.size());
                qs.add(seg.get(i));
            }
            t += d;
            q = qe;
        }
        double[] ta = new double[times.size()];
        Vec3[] tcp = new Vec3[times.size()];
        // Thousands of samples: forward kinematics into one buffer where the kinematics module answers.
        Optional<KinematicModel> km = k.kinematicModel();
        KinematicModel.Workspace ws = km.map(KinematicModel::newWorkspace).orElse(null);
        double[] f = new double[12];
        Vec3 tt = flangeTtcp.position();
        for (int i = 0; i < ta.length; i++) {
            ta[i] = times.get(i);
            if (ws == null) {
                tcp[i] = worldTbase.times(k.flange(qs.get(i))).times(flangeTtcp).position();
                continue;
            }
            km.get().flange(qs.get(i), ws, f);
            tcp[i] = worldTbase.apply(new Vec3(f[0] * tt.x() + f[1] * tt.y() + f[2] * tt.z() + f[3],
                    f[4] * tt.x() + f[5] * tt.y() + f[6] * tt.z() + f[7], f[8] * tt.x() + f[9] * tt.y() + f[10] * tt.z() + f[11]));
        }
        return new ProgramRun(program, module, report, out, bad, ta, qs.toArray(new double[0][]), tcp);
    }

    /** Messages for a log: one line per problem, by instruction and target. */
    public List<String> problemLines() {
        List<String> lines = new ArrayList<>();
        for (Step s : steps)
            for (Problem p : s.problems())
                lines.add(String.format(Locale.ROOT, "instruction %d (%s), target %s: %s %s: %s", s.index() + 1,
                        s.instruction(), p.target(), p.severity(), p.kind().name().toLowerCase(Locale.ROOT), p.message()));
        return lines;
    }
}
