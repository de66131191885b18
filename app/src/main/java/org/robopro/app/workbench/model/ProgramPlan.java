package org.robopro.app.workbench.model;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.Vec3;

/**
 * A program checked and sampled for playback: for each instruction whether it can be executed
 * (target known, reachable, inside the joint limits, MoveL line reachable without a
 * configuration flip), and a timeline of joint values (MoveJ interpolated in joint space, MoveL
 * along the straight TCP line with IK at each sample). This is the workbench's thin view of
 * path checking until the programs module's checks are wired in.
 */
public final class ProgramPlan {
    /** The outcome for one instruction. */
    public record Step(int index, Instruction instruction, boolean ok, String message) { }

    private final List<Step> steps;
    private final double[] times;
    private final double[][] qs;
    private final Vec3[] tcpWorld;

    private ProgramPlan(List<Step> steps, double[] times, double[][] qs, Vec3[] tcpWorld) {
        this.steps = List.copyOf(steps);
        this.times = times;
        this.qs = qs;
        this.tcpWorld = tcpWorld;
    }

    public List<Step> steps() { return steps; }
    public boolean ok() { return steps.stream().allMatch(Step::ok); }
    public int sampleCount() { return times.length; }
    public double duration() { return times.length == 0 ? 0 : times[times.length - 1]; }
    public Vec3 tcp(int i) { return tcpWorld[i]; }
    public double[] qAt(int i) { return qs[i].clone(); }

    /** Joint values at time t (s), linearly interpolated between samples. */
    public double[] qAtTime(double t) {
        if (times.length == 0) throw new IllegalStateException("empty plan");
        if (t <= times[0]) return qs[0].clone();
        for (int i = 1; i < times.length; i++) {
            if (t <= times[i]) {
                double s = (t - times[i - 1]) / Math.max(1e-12, times[i] - times[i - 1]);
                double[] a = qs[i - 1], b = qs[i], out = new double[a.length];
                for (int k = 0; k < a.length; k++) out[k] = a[k] + s * (b[k] - a[k]);
                return out;
            }
        }
        return qs[qs.length - 1].clone();
    }

    /** Largest joint step (rad) between two MoveL samples before we call it a configuration flip. */
    static final double FLIP = Math.toRadians(30);

    public static ProgramPlan of(WorkbenchModel m) {
        List<Instruction> program = m.program();
        RobotKinematics k = m.kinematics();
        List<JointDescription> joints = k.description().joints();
        List<Step> steps = new ArrayList<>();
        List<Double> times = new ArrayList<>();
        List<double[]> qs = new ArrayList<>();
        double[] q = null;
        double t = 0;
        for (int i = 0; i < program.size(); i++) {
            Instruction ins = program.get(i);
            Optional<Target> target = m.target(ins.target());
            if (target.isEmpty()) { steps.add(new Step(i, ins, false, "no target named " + ins.target())); continue; }
            Target tg = target.get();
            Optional<double[]> end = m.solveTcp(tg.worldTtcp(), tg.qTaught());
            if (end.isEmpty()) { steps.add(new Step(i, ins, false, tg.name() + " is out of reach")); continue; }
            int bad = k.firstLimitViolation(end.get());
            if (bad >= 0) {
                steps.add(new Step(i, ins, false, String.format(java.util.Locale.ROOT,
                        "%s needs joint %d at %.1f deg, outside %.0f..%.0f deg", tg.name(), bad + 1,
                        Math.toDegrees(end.get()[bad]), Math.toDegrees(joints.get(bad).min()), Math.toDegrees(joints.get(bad).max()))));
                continue;
            }
            if (q == null) {
                q = end.get();
                times.add(t);
                qs.add(q);
                steps.add(new Step(i, ins, true, "start at " + tg.name()));
                continue;
            }
            double v = ins.speedMmPerS() / 1000.0;
            if (ins.type() == Instruction.Type.MOVEJ) {
                double[] qe = end.get();
                double dur = m.worldTtcp(q).distanceTo(tg.worldTtcp()) / v;
                for (int j = 0; j < qe.length; j++)
                    dur = Math.max(dur, Math.abs(qe[j] - q[j]) / joints.get(j).maxSpeed());
                int n = 24;
                double[] q0 = q;
                for (int s = 1; s <= n; s++) {
                    double[] qi = new double[q0.length];
                    for (int j = 0; j < qi.length; j++) qi[j] = q0[j] + (qe[j] - q0[j]) * s / n;
                    times.add(t + dur * s / n);
                    qs.add(qi);
                }
                t += dur;
                q = qe;
                steps.add(new Step(i, ins, true, String.format(java.util.Locale.ROOT, "%.2f s", dur)));
            } else {
                Pose a = m.worldTtcp(q), b = tg.worldTtcp();
                double dist = a.distanceTo(b);
                double dur = Math.max(dist / v, 1e-3);
                int n = Math.max(2, (int) Math.ceil(dist / 0.01));
                Vec3 rv = a.inverse().times(b).rotationVector();
                double[] qi = q;
                String fail = null;
                List<double[]> seg = new ArrayList<>();
                for (int s = 1; s <= n; s++) {
                    double f = (double) s / n;
                    Pose p = Pose.translation(a.position().plus(b.position().minus(a.position()).times(f)))
                            .times(Pose.translation(a.position().times(-1)).times(a))
                            .times(rv.norm() < 1e-12 ? Pose.IDENTITY : Pose.rotAxis(rv, rv.norm() * f));
                    Optional<double[]> sol = m.solveTcp(p, qi);
                    if (sol.isEmpty()) { fail = String.format(java.util.Locale.ROOT, "line to %s leaves the workspace at %.0f %%", tg.name(), 100 * f); break; }
                    double jump = 0;
                    for (int j = 0; j < qi.length; j++) jump = Math.max(jump, Math.abs(sol.get()[j] - qi[j]));
                    if (jump > FLIP) { fail = String.format(java.util.Locale.ROOT, "line to %s passes a singularity or flips configuration at %.0f %%", tg.name(), 100 * f); break; }
                    int lim = k.firstLimitViolation(sol.get());
                    if (lim >= 0) { fail = String.format(java.util.Locale.ROOT, "line to %s drives joint %d outside its limits at %.0f %%", tg.name(), lim + 1, 100 * f); break; }
                    qi = sol.get();
                    seg.add(qi);
                }
                if (fail != null) { steps.add(new Step(i, ins, false, fail)); continue; }
                for (int s = 0; s < seg.size(); s++) {
                    times.add(t + dur * (s + 1) / n);
                    qs.add(seg.get(s));
                }
                t += dur;
                q = qi;
                steps.add(new Step(i, ins, true, String.format(java.util.Locale.ROOT, "%.2f s, %.0f mm", dur, dist * 1000)));
            }
        }
        double[] ta = new double[times.size()];
        Vec3[] tcp = new Vec3[times.size()];
        for (int i = 0; i < ta.length; i++) {
            ta[i] = times.get(i);
            tcp[i] = m.worldTtcp(qs.get(i)).position();
        }
        return new ProgramPlan(steps, ta, qs.toArray(new double[0][]), tcp);
    }
}
