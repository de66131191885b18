package org.robopro.programs.compensation;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.calibration.compensation.TargetCompensator;
import org.robopro.calibration.compensation.TargetCompensator.Status;
import org.robopro.kinematics.IkSolution;
import org.robopro.programs.Declaration;
import org.robopro.programs.ModuleItem;
import org.robopro.programs.Move;
import org.robopro.programs.Procedure;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.Statement;
import org.robopro.programs.Teach;
import org.robopro.programs.rapid.RapidAst;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;

/**
 * Compensated export: rewrites a program's robtargets so that a robot whose real geometry is
 * the calibrated model reaches the intended poses while its controller knows only the nominal
 * model (seed paper §5, Fig. 5). Each named target is compensated with the tool and work object
 * of the first instruction that uses it; confdata comes from the nominal IK solution the
 * controller will use. Joint targets are left as they are (the controller moves the joints).
 * The compensation itself is the calibration module's {@link TargetCompensator}.
 */
public final class ProgramCompensation {
    private ProgramCompensation() { }

    /**
     * One target's correction: how far the commanded pose moved (m, rad) and what is left.
     * {@code status} is empty when the target was not compensated, and {@code notCompensated} says why.
     */
    public record Correction(String target, double shiftM, double turnRad, double residualM, double residualRad,
                             Optional<Status> status, String notCompensated) {
        /** Whether the target was compensated and the result may be sent to the controller. */
        public boolean ok() { return status.isPresent() && status.get().ok(); }

        @Override public String toString() {
            return String.format(Locale.ROOT, "%-24s shift %8.3f mm  turn %7.4f deg  residual %.2e mm %.2e deg  %s", target,
                    shiftM * 1e3, Math.toDegrees(turnRad), residualM * 1e3, Math.toDegrees(residualRad),
                    status.map(Status::label).orElse("not compensated: " + notCompensated));
        }
    }

    public record Outcome(RapidModule module, List<Correction> corrections) {
        public Outcome {
            corrections = List.copyOf(corrections);
        }
    }

    /** Compensates every robtarget of {@code module} run from procedure {@code entry}. */
    public static Outcome compensate(RapidModule module, String entry, KinematicModel nominal, TargetCompensator compensator) {
        InverseKinematics ik = InverseKinematics.of(nominal);
        MotionInterpreter interpreter = MotionInterpreter.of(module);
        List<MoveStep> steps = interpreter.moves(entry);
        Map<String, RobTarget> replaced = new LinkedHashMap<>();
        List<Correction> corrections = new ArrayList<>();
        // Each named robtarget is compensated once, at its first use: as a Move's to-point or as a
        // MoveC's circle point (the circle must pass through the real point too).
        Map<String, Use> firstUse = new LinkedHashMap<>();
        for (MoveStep s : steps) {
            if (s.kind() == Move.Kind.MOVE_ABS_J) continue;
            firstUse.putIfAbsent(s.targetName().toLowerCase(Locale.ROOT), Use.to(s));
            if (s.circName().isPresent() && s.baseTtcpCirc().isPresent())
                firstUse.putIfAbsent(s.circName().get().toLowerCase(Locale.ROOT), Use.circ(s));
        }
        for (Map.Entry<String, Use> e : firstUse.entrySet()) {
            String key = e.getKey();
            if (key.equals("*")) continue; // inline targets: below
            Declaration d = module.declaration(key).orElse(null);
            if (d == null || !(d.value() instanceof RobTarget t)) continue;
            replaced.put(key, compensateOne(d.name(), t, e.getValue(), ik, compensator, corrections));
        }
        // Inline targets robopro can rewrite: those of a typed Move statement (a procedure's own statement).
        Map<RapidAst.Stmt, Move> rewritable = new IdentityHashMap<>();
        for (Procedure p : module.procedures())
            for (Statement st : p.body())
                if (st instanceof Move m && m.kind() != Move.Kind.MOVE_ABS_J && hasInline(m))
                    rewritable.put((RapidAst.Stmt) module.node(m).orElseThrow(), m);
        reportUnrewritten(module, steps, rewritable, corrections);
        // Where each rewritable statement first ran; a procedure not run from the entry is run on its own.
        Map<RapidAst.Stmt, MoveStep> firstRun = new IdentityHashMap<>();
        for (MoveStep s : steps) s.statement().ifPresent(st -> firstRun.putIfAbsent(st, s));
        List<ModuleItem> items = new ArrayList<>();
        for (ModuleItem it : module.items()) {
            if (it instanceof Declaration d && replaced.containsKey(d.name().toLowerCase(Locale.ROOT)))
                items.add(d.withValue(replaced.get(d.name().toLowerCase(Locale.ROOT))));
            else if (it instanceof Procedure p)
                items.add(inlineCompensated(p, module, firstRun, interpreter, ik, compensator, corrections));
            else items.add(it);
        }
        return new Outcome(module.withItems(items), corrections);
    }

    private static boolean hasInline(Move m) {
        return m.toPoint() instanceof Ref.Inline<?> || m.circPoint().filter(c -> c instanceof Ref.Inline<?>).isPresent();
    }

    /**
     * Targets robopro cannot rewrite are named in the corrections rather than passed over
     * silently: a target computed by an expression ({@code Offs(p1, ...)}, {@code RelTool}) or
     * written inline in a statement inside a loop, branch or process instruction.
     */
    private static void reportUnrewritten(RapidModule module, List<MoveStep> steps, Map<RapidAst.Stmt, Move> rewritable,
                                          List<Correction> corrections) {
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (MoveStep s : steps) {
            if (s.kind() == Move.Kind.MOVE_ABS_J) continue;
            List<String> names = new ArrayList<>(List.of(s.targetName()));
            s.circName().ifPresent(names::add);
            for (String n : names) {
                String where = (s.context().isEmpty() ? "" : s.context() + " > ") + s.procedure() + "#" + (s.statementIndex() + 1)
                        + s.source().map(p -> " (line " + p.line() + ")").orElse("");
                if (n.equals("*")) {
                    boolean typed = s.statement().filter(rewritable::containsKey).isPresent();
                    if (!typed && seen.add(where + " *"))
                        corrections.add(new Correction(where + " *", 0, 0, Double.NaN, Double.NaN, Optional.empty(),
                                "inline target of " + s.instruction() + " in a loop, branch or process instruction (not rewritten: name it)"));
                } else if (module.declaration(n.toLowerCase(Locale.ROOT)).filter(d -> d.value() instanceof RobTarget).isEmpty()
                        && seen.add(n.toLowerCase(Locale.ROOT)))
                    corrections.add(new Correction(n, 0, 0, Double.NaN, Double.NaN, Optional.empty(),
                            "computed at run time (" + where + "); only its named robtargets are compensated"));
            }
        }
    }

    /** {@code p} (a procedure of {@code module}) with its inline robtargets compensated where each statement first ran. */
    private static Procedure inlineCompensated(Procedure p, RapidModule module, Map<RapidAst.Stmt, MoveStep> firstRun,
                                               MotionInterpreter interpreter, InverseKinematics ik, TargetCompensator c,
                                               List<Correction> corrections) {
        List<Statement> body = new ArrayList<>();
        boolean changed = false;
        for (int k = 0; k < p.body().size(); k++) {
            Statement st = p.body().get(k);
            if (!(st instanceof Move m) || m.kind() == Move.Kind.MOVE_ABS_J || !hasInline(m)) {
                body.add(st);
                continue;
            }
            RapidAst.Stmt node = (RapidAst.Stmt) module.node(m).orElseThrow();
            if (!firstRun.containsKey(node))
                for (MoveStep s : interpreter.moves(p.name())) s.statement().ifPresent(n -> firstRun.putIfAbsent(n, s));
            MoveStep s = firstRun.get(node);
            if (s == null) { // skipped by a RETURN or GOTO before it: nothing tells where it would move
                corrections.add(new Correction(p.name() + "#" + (k + 1) + " *", 0, 0, Double.NaN, Double.NaN, Optional.empty(),
                        "inline target of a statement that never runs"));
                body.add(st);
                continue;
            }
            Move out = m;
            if (m.toPoint() instanceof Ref.Inline<?> to) {
                RobTarget t = compensateOne(p.name() + "#" + (k + 1) + " *", (RobTarget) to.value(), Use.to(s), ik, c, corrections);
                out = out.withToPoint(Ref.inline(t));
            }
            if (m.circPoint().isPresent() && m.circPoint().get() instanceof Ref.Inline<?> via) {
                RobTarget t = compensateOne(p.name() + "#" + (k + 1) + " circle *", (RobTarget) via.value(), Use.circ(s), ik, c, corrections);
                out = out.withCircPoint(Ref.inline(t));
            }
            body.add(out);
            changed = true;
        }
        return changed ? p.withBody(body) : p;
    }

    /** Where a target is used: the base poses it commands there, and the step's tool and work object. */
    private record Use(Pose baseTflange, Pose baseTtcp, MoveStep step) {
        static Use to(MoveStep s) { return new Use(s.baseTflange().orElseThrow(), s.baseTtcp().orElseThrow(), s); }

        static Use circ(MoveStep s) { return new Use(s.baseTflangeCirc().orElseThrow(), s.baseTtcpCirc().orElseThrow(), s); }
    }

    private static RobTarget compensateOne(String name, RobTarget t, Use use, InverseKinematics ik, TargetCompensator c,
                                           List<Correction> corrections) {
        MoveStep s = use.step();
        if (!s.tool().robhold() || s.wobj().robhold()) {
            corrections.add(new Correction(name, 0, 0, Double.NaN, Double.NaN, Optional.empty(), "stationary tool"));
            return t;
        }
        Pose baseTtcp = use.baseTtcp();
        Optional<IkSolution> start = ik.solveWithConf(use.baseTflange(), t.robconf());
        double[] seed = start.map(IkSolution::q).orElseGet(() -> new double[ik.model().dof()]);
        TargetCompensator.Result r = c.compensate(baseTtcp, s.flangeTtcp(), seed);
        Pose baseTobj = Teach.baseTobj(s.wobj());
        Pose objTcommanded = baseTobj.inverse().times(r.commanded());
        corrections.add(new Correction(name, r.commanded().distanceTo(baseTtcp), r.commanded().angleTo(baseTtcp),
                r.residualM(), r.residualRad(), Optional.of(r.status()), ""));
        if (!r.status().ok()) return t; // keep the target; the report says why
        return new RobTarget(objTcommanded.position(), Quaternion.of(objTcommanded), ik.confOf(r.q()), t.extax());
    }
}
